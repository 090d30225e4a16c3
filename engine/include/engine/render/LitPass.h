#pragma once
// The forward lit pass: draws every mesh instance with the material model and lights of
// lit.frag, the plugin's visibility hook inserted. It also draws the shadow-mask views
// (one light's shade as gray) with the same program, so masks show exactly what shading
// used.
// With RendererConfig::msaa above 1 the shaded image is drawn multisampled and resolved by a
// pass of its own; the per-light views stay single-sampled: their pixels are measured.
// The pieces it is made of: its programs (LitPrograms.h), its lights' block (LitLights.h),
// the shade cache (ShadeCache.h) and the split by light footprints (FootprintSplit.h).
#include "engine/config/EngineConfig.h"
#include "engine/gl/FramebufferCache.h"
#include "engine/gl/Program.h"
#include "engine/render/Frame.h"
#include "engine/render/LitLights.h"
#include "engine/render/LitPrograms.h"
#include "engine/render/MaterialShading.h"
#include "engine/render/ShadeCache.h"
#include "engine/scene/ScreenFootprint.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace engine {

// The shaded image's format (8-bit sRGB, as read back and displayed), and the depth format
// of every lit pass.
inline constexpr TextureFormat kLitColorFormat = TextureFormat::SRGB8_A8;
inline constexpr TextureFormat kLitDepthFormat = TextureFormat::Depth32F;

// What will move once warm-up ends (Renderer::warmUp), so that it compiles what the first
// moving frames draw with: the camera or the scene's geometry (every cached light's shade
// changes every frame), and the lights, by slot, that move on their own.
struct ExpectedMotion {
    bool cameraOrGeometry = false;
    std::vector<int> lights;
    bool any() const { return cameraOrGeometry || !lights.empty(); }
};

class LitPass {
public:
    LitPass(const RendererConfig& config, const RendererSwitches& switches);

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
    // The clustered lit pass's last tile lists (LightTiles.h): their entries over all tiles,
    // and the longest list (0 when the pass was not clustered).
    std::int64_t tileListEntries() const { return tileListEntries_; }
    int longestTileList() const { return longestTileList_; }
    const LightTiles& lightTiles() const { return lightTiles_; }
    // A new scene: nothing cached is still right.
    void sceneChanged();

    // What a per-light view shows: the shade (gray, 255 = lit) or the hook's debug picture.
    enum class LightView { ShadowMask, Comparison };
    // Adds a pass drawing light `slot`'s view into `target` (an imported RGBA8 texture).
    void addLightViewTo(Frame& frame, int slot, LightView view, ResourceHandle target);

    // While warming up (Renderer::warmUp), a frame compiles every program it could use; after
    // it, a frame compiles only what it cannot draw without: a region of the footprint split
    // whose programs are missing is drawn unsplit instead (the same image: outside its
    // footprint a light adds exactly nothing). With `motion`, the warm-up also compiles (and
    // draws once) the programs that motion asks for next (ShadeCache's Compute and Moving
    // sources, whole target and split), so that the first moving frames compile nothing.
    void setWarmingUp(bool warmingUp, const ExpectedMotion& motion = {});

private:
    void addPass(Frame& frame, const std::string& name, ResourceHandle target, LitOutput output, int maskSlot);
    // A pass resolving the multisampled `drawn` into `target` (glBlitFramebuffer).
    void addResolvePass(Frame& frame, const std::string& name, ResourceHandle drawn, ResourceHandle target);
    // A pass's programs by material variant; null where no primitive of the scene needs it.
    using Variants = std::array<const gl::Program*, kMaterialFeatureCombinations>;
    // A rectangle of the target drawn with programs of its own: the shaded image's lights
    // whose footprint misses it take a constant shade there (ShadingRegions.h).
    struct Region {
        PixelRect rect;
        Variants programs{};
        bool evaluatesHook = false;  // its programs hold the visibility hook's code
    };
    void drawScene(const Frame& frame, const std::vector<Region>& regions, PassContext& context);
    // The hook a region drawn with `plan` needs in its programs (null: none of its code).
    const LightVisibilityHook* hookFor(const Frame& frame, const ShadeCache::Plan& plan, LitOutput output) const;
    // Whether every material variant's program for `plan` is compiled.
    bool compiledFor(const Frame& frame, const ShadeCache::Plan& plan, LitOutput output, const std::string& lights,
                     const std::vector<unsigned>& variants) const;
    // A program to draw once during warm-up, with the material variant it draws.
    struct WarmUpDraw {
        const gl::Program* program;
        unsigned variant;
        bool evaluatesHook;
        int writtenLayers;      // the shade cache's layers it writes (0: none)
        unsigned fetchedArray;  // the shade cache's array it reads (0: none)
    };
    // The shaded image's programs under the expected motion (setWarmingUp): the whole
    // target's and every region's a split may cut (up to kMaxWarmedUpSplitLights).
    std::vector<WarmUpDraw> compileForMotion(const Frame& frame, const std::string& lights,
                                             const std::vector<unsigned>& variants);
    // Passes drawing each of `draws` once into one-pixel images of the shaded image's formats
    // and state (and the shade cache's layers it writes): a driver that compiles a program's
    // code at its first draw (llvmpipe does) compiles it here, not in the first frame that
    // moves. One pass per number of written layers.
    void addWarmUpPasses(Frame& frame, const std::vector<WarmUpDraw>& draws);
    void addWarmUpPass(Frame& frame, int writtenLayers, std::vector<WarmUpDraw> draws);
    // The clustered pass's lights and tile lists for this frame, bound.
    void uploadClusteredLights(const Frame& frame, const std::vector<float>& dimming);
    // One mesh instance's primitives with `programs`; `current` is the program in use.
    void drawInstance(const Frame& frame, int index, const glm::dmat4& view, const Variants& programs,
                      const gl::Program*& current, PassContext& context);

    RendererConfig config_;
    RendererSwitches switches_;
    LitPrograms programs_;
    LitLights lights_;
    ClusteredLights clusteredLights_;
    LightTiles lightTiles_;  // the clustered pass's last
    std::int64_t tileListEntries_ = 0;
    int longestTileList_ = 0;
    int culledInstances_ = 0;
    ShadeCache shadeCache_;
    ShadeCache::Plan shadePlan_;  // of this frame's shaded image
    std::vector<int> footprintLimitedLights_;
    int shadingRegionCount_ = 1;
    bool warmingUp_ = false;
    ExpectedMotion expectedMotion_;  // while warming up
    std::uint64_t sceneGeneration_ = 0;
    gl::FramebufferCache resolveSources_;  // the multisampled images the resolve reads
};

} // namespace engine
