#include "technique/DepthPassStyle.h"

namespace shadowmap {

glm::vec3 signedOffset(const glm::vec2& offset, const DepthPassStyle& style) {
    const float sign = style.reversedZ ? -1.0f : 1.0f;
    return sign * glm::vec3(offset, style.offsetClamp);
}

engine::PassState depthPassState(const DepthPassStyle& style) {
    engine::PassState state;
    state.depthTest = style.reversedZ ? engine::PassState::DepthTest::Greater : engine::PassState::DepthTest::Less;
    state.clipDepth = style.reversedZ ? engine::PassState::ClipDepth::ZeroToOne
                                      : engine::PassState::ClipDepth::NegativeOneToOne;
    state.cull = style.backFacesOnly ? engine::PassState::Cull::Front : engine::PassState::Cull::None;
    if (style.polygonOffset != glm::vec2(0.0f)) {
        const glm::vec3 offset = signedOffset(style.polygonOffset, style);
        state.offsetFactor = offset.x;
        state.offsetUnits = offset.y;
        state.offsetClamp = offset.z;
    }
    if (style.inAtlas()) {
        state.viewportX = style.atlasViewport.x;
        state.viewportY = style.atlasViewport.y;
        state.viewportWidth = state.viewportHeight = style.atlasViewport.size;
        state.scissorToViewport = true;
    }
    return state;
}

engine::PassTargets depthPassTargets(engine::ResourceHandle map, int layer, const DepthPassStyle& style) {
    return engine::PassTargets::depthOnly(map, layer, style.reversedZ ? 0.0f : 1.0f);
}

} // namespace shadowmap
