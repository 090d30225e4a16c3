#pragma once
// The outdoor street's sun (tests/support/OutdoorScene.h) rendered with given settings and
// scored against the analytic truth on its ground: what the cascade and LiSPSM tests compare.
#include "../../support/OutdoorScene.h"
#include "AnalyticShadows.h"

namespace engine::test {

// The sun's mask with `shadow` settings through the street camera, against the truth on the
// ground pixels where `inside(p)` holds, leaving out those within edgeRadius pixels of a
// truth edge. `sun`, when given, receives the sun's shadow view.
inline MaskStats outdoorGroundErrors(const std::vector<RenderPlugin*>& plugins, const nlohmann::json& shadow,
                                     int width, int height, const std::function<bool(const glm::dvec3&)>& inside,
                                     int edgeRadius = 2, ShadowView* sun = nullptr) {
    const OutdoorScene outdoor = makeOutdoorScene(shadow);
    const FrameCamera camera = outdoorCamera(width, height);
    FrameResult frame;
    const auto mask = renderShadowMask(plugins, outdoor.scene, camera, outdoor.sunSlot, &frame);
    if (sun) *sun = *frame.shadowView(outdoor.sunSlot);
    return compareFloorMask(mask, outdoor.scene, outdoor.sunSlot, camera, outdoor.occluders, 0.0,
                            OutdoorScene::kGroundHalf, inside, edgeRadius);
}

// Whether p lies within `distance` of the street camera's eye.
inline std::function<bool(const glm::dvec3&)> withinOfOutdoorCamera(double distance) {
    const glm::dvec3 eye = outdoorCamera(1, 1).position();
    return [eye, distance](const glm::dvec3& p) { return glm::length(p - eye) < distance; };
}

} // namespace engine::test
