#pragma once
// The lit pass's visibility hook of one frame (engine/render/Frame.h): every shadowed
// light's lookup entries in the uniform block (ShadowBlock.h, by its projection), its map on
// its texture unit, the GLSL for this layout of maps (HookGlsl.h), and the shade keys that
// let the lit pass reuse a light's shade while its map and lookup hold.
#include "plugin/HookGlsl.h"
#include "plugin/LightShadow.h"

#include "engine/gl/Buffer.h"
#include "engine/gl/Sampler.h"
#include "engine/render/Frame.h"

#include <functional>
#include <string>
#include <vector>

namespace shadowmap {

class ShadowHook {
public:
    using Warn = std::function<void(const LightShadow&, const std::string&)>;

    // cacheMaps: give the lit pass shade keys (without map caching nothing is reused).
    // maxTextureUnits: GL_MAX_TEXTURE_IMAGE_UNITS (raw-depth views use the top units).
    engine::LightVisibilityHook build(const engine::Frame& frame, const std::vector<LightShadow>& lights,
                                      bool cacheMaps, int maxTextureUnits, const Warn& warn);
    std::size_t layouts() const { return hookGlsl_.layouts(); }

private:
    const engine::gl::Sampler& rawDepthSampler();  // comparison off: reads a map's depth

    engine::gl::Sampler rawDepthSampler_;
    engine::gl::Buffer shadowBlock_;  // ShadowBlock.h, refilled every frame
    HookGlsl hookGlsl_;               // the hook's code per map layout
};

} // namespace shadowmap
