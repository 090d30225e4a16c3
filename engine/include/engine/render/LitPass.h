#pragma once
// The forward lit pass: draws every mesh instance with the material model and lights of
// lit.frag, the plugin's visibility hook inserted. It also draws the shadow-mask views
// (one light's shade as gray) with the same program, so masks show exactly what shading
// used.
#include "engine/config/EngineConfig.h"
#include "engine/gl/Buffer.h"
#include "engine/gl/Program.h"
#include "engine/render/Frame.h"
#include "engine/render/MaterialShading.h"
#include "engine/render/ShadeCache.h"
#include "engine/scene/ScreenFootprint.h"

#include <array>
#include <compare>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace engine {

class LitPass {
public:
    explicit LitPass(const RendererConfig& config);

    // Adds the lit pass writing `colorTarget` (an imported texture) to the frame's graph.
    void addTo(Frame& frame, ResourceHandle colorTarget);
    // Mesh instances the last drawn pass skipped because they lie outside the view.
    int culledInstances() const { return culledInstances_; }
    // Where the last shaded image took each light's shade from (ShadeCache.h).
    const ShadeCache::Plan& shadePlan() const { return shadePlan_; }
    // The lights whose shadow the last shaded image looked up only inside their screen
    // footprint (ShadingRegions.h), by slot, and the regions that split its target into (1:
    // not split).
    const std::vector<int>& footprintLimitedLights() const { return footprintLimitedLights_; }
    int shadingRegionCount() const { return shadingRegionCount_; }
    // A new scene: nothing cached is still right.
    void sceneChanged();

    // What a per-light view shows: the shade (gray, 255 = lit) or the hook's debug picture.
    enum class LightView { ShadowMask, Comparison };
    // Adds a pass drawing light `slot`'s view into `target` (an imported RGBA8 texture).
    void addLightViewTo(Frame& frame, int slot, LightView view, ResourceHandle target);

    // How many lit programs have been compiled so far (Renderer::warmUp waits for it to stop growing).
    std::size_t programCount() const { return programs_.size(); }

private:
    enum class Output { Color, ShadowMask, Comparison };  // lit.frag's views
    void addPass(Frame& frame, const std::string& name, ResourceHandle target, Output output,
                 int maskSlot);
    // One program per hook source, lights (count and types), output view, shade-cache
    // plan (fetched / computed lights) and material variant (MaterialShading.h feature
    // bits), compiled on first use.
    const gl::Program& programFor(const LightVisibilityHook* hook, const std::string& lightDefinesGlsl,
                                  Output output, const std::string& loadShadesGlsl, unsigned variant);
    // A pass's programs by material variant; null where no primitive of the scene needs it.
    using Variants = std::array<const gl::Program*, kMaterialFeatureCombinations>;
    // A rectangle of the target drawn with programs of its own: the shaded image's lights
    // whose footprint misses it take a constant shade there (ShadingRegions.h).
    struct Region {
        PixelRect rect;
        Variants programs{};
        bool evaluatesHook = false;  // its programs hold the visibility hook's code
    };
    // The shaded image's regions and the shade plan of each: one region, the whole target,
    // unless some evaluated light's footprint leaves enough of the target out.
    std::vector<std::pair<PixelRect, ShadeCache::Plan>> footprintRegions(const Frame& frame);
    void uploadLights(const Scene& scene, const FrameCamera& camera);
    void drawScene(const Frame& frame, const std::vector<Region>& regions, PassContext& context);
    // One mesh instance's primitives with `programs`; `current` is the program in use.
    void drawInstance(const Frame& frame, int index, const glm::dmat4& view, const Variants& programs,
                      const gl::Program*& current, PassContext& context);

    // What a lit program is compiled from, without its text: the hook by owner and version
    // (Frame.h), the light and shade-cache defines (a few lines), output and variant.
    struct ProgramKey {
        std::string hookIdentity;  // its owner; empty: no hook (or none of its code needed)
        std::uint64_t hookVersion = 0;
        std::string lightDefines, loadShades;
        Output output = Output::Color;
        unsigned variant = 0;
        auto operator<=>(const ProgramKey&) const = default;
    };

    RendererConfig config_;
    std::map<ProgramKey, std::unique_ptr<gl::Program>> programs_;
    gl::Buffer lightBuffer_;
    int lightCount_ = 0;
    int culledInstances_ = 0;
    ShadeCache shadeCache_;
    ShadeCache::Plan shadePlan_;  // of this frame's shaded image
    std::vector<int> footprintLimitedLights_;
    int shadingRegionCount_ = 1;
    std::uint64_t sceneGeneration_ = 0;
};

} // namespace engine
