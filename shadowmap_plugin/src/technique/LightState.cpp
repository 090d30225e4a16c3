#include "technique/LightState.h"

namespace shadowmap {

namespace {
// Cube faces in GL order (GL_TEXTURE_CUBE_MAP_POSITIVE_X + i), as pass names show them.
constexpr const char* kFaceNames[engine::kCubeFaces] = {"+x", "-x", "+y", "-y", "+z", "-z"};
// Cascades: "_c0" (nearest) .. "_c3".
std::string layerSuffix(MapKind kind, int layer) {
    if (layer < 0) return "";
    return kind == MapKind::Cascades ? "_c" + std::to_string(layer) : std::string("_") + kFaceNames[layer];
}
} // namespace

std::string LightState::mapResource() const { return "shadow_map_" + std::to_string(slot); }

std::string LightState::depthPass(int layer) const {
    return "shadow_" + std::to_string(slot) + "_" + name + layerSuffix(frame.kind, layer);
}
std::string LightState::firstLayerPass(int layer) const { return depthPass(layer) + "_first_layer"; }
std::string LightState::firstLayerResource(int layer) const {
    return "shadow_first_layer_" + std::to_string(slot) + layerSuffix(frame.kind, layer);
}

std::string LightState::momentsResource() const { return "shadow_moments_" + std::to_string(slot); }
std::string LightState::momentsPass(int layer) const { return depthPass(layer) + "_moments"; }
std::string LightState::momentsBlurPass(int layer) const { return depthPass(layer) + "_moments_blur"; }
std::string LightState::momentsRowsResource(int layer) const {
    return "shadow_moments_rows_" + std::to_string(slot) + layerSuffix(frame.kind, layer);
}

std::string LightState::visibilityResource() const { return "shadow_visibility_" + std::to_string(slot); }
std::string LightState::stencilCountResource() const { return "shadow_stencil_count_" + std::to_string(slot); }
std::string LightState::volumePass() const { return "shadow_" + std::to_string(slot) + "_" + name + "_volumes"; }

} // namespace shadowmap
