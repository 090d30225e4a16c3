#pragma once
// The forward lit pass: draws every mesh instance with the material model and lights of
// lit.frag, the plugin's visibility hook inserted. It also draws the shadow-mask views
// (one light's shade as gray) with the same program, so masks show exactly what shading
// used.
#include "engine/config/EngineConfig.h"
#include "engine/gl/Buffer.h"
#include "engine/gl/Program.h"
#include "engine/render/Frame.h"

#include <map>
#include <memory>
#include <string>

namespace engine {

class LitPass {
public:
    explicit LitPass(const RendererConfig& config);

    // Adds the lit pass writing `colorTarget` (an imported texture) to the frame's graph.
    void addTo(Frame& frame, ResourceHandle colorTarget);
    // Mesh instances the last drawn pass skipped because they lie outside the view.
    int culledInstances() const { return culledInstances_; }

    // What a per-light view shows: the shade (gray, 255 = lit) or the hook's debug picture.
    enum class LightView { ShadowMask, Comparison };
    // Adds a pass drawing light `slot`'s view into `target` (an imported RGBA8 texture).
    void addLightViewTo(Frame& frame, int slot, LightView view, ResourceHandle target);

private:
    enum class Output { Color = 0, ShadowMask = 1, Comparison = 2 };  // lit.frag's modes
    void addPass(Frame& frame, const std::string& name, ResourceHandle target, Output output,
                 int maskSlot);
    // One program per hook source, light count and debug variant, compiled on first use.
    const gl::Program& programFor(const std::string& visibilityGlsl, int lightCount, bool debugView);
    void uploadLights(const Scene& scene, const FrameCamera& camera);
    void drawScene(const Frame& frame, const gl::Program& program, PassContext& context);

    RendererConfig config_;
    std::map<std::string, std::unique_ptr<gl::Program>> programs_;  // by full header + hook
    gl::Buffer lightBuffer_;
    int lightCount_ = 0;
    int culledInstances_ = 0;
};

} // namespace engine
