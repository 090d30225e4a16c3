#include "technique/projection/CubeMapProjection.h"

#include "technique/MapCacheKey.h"
#include "technique/NormalOffsetData.h"
#include "technique/SoftShadowLayers.h"
#include "technique/projection/FiniteMatrix.h"

#include <cmath>

namespace shadowmap {

namespace {
// Cube maps: the reference depth is lowered by the depth a 45-degree surface spans across
// this many texels of the face (visibility.glsl, shadowMapCube). The faces are axis-aligned
// in world space, so a surface facing a face's axis (any floor under a point light) has zero
// depth slope in that face and the slope-scaled polygon offset gives it no margin at all:
// a small step in it (2CylinderEngine's crankcase top: about 0.07 units, judged by the 4000
// d24 offset units that also hide it) shadowed up to half a texel beside it, a dotted acne
// line that the spot light at the same place, its axis tilted to that surface, does not
// show. Measured with
// engine-render --truth (1280x720, 2048 maps, d24, pcf), acne / leak in percent:
//   bias        0       0.1     0.25    0.5     1
//   engine      1.197   1.113   1.042   0.949   0.809   (key point light; leak 0.342 .. 0.374)
//   showcase    0.070                   0.064           (point_light; leak 0.028 at both)
// 0.5 removes the line (acne -0.25 points for +0.016 leak); tools/shadowmap-stress --quick:
// the point light's acne summed over its cases 18.9 -> 14.1, leak and every other light as
// before, no case worse. Larger biases trade more leak for acne the polygon offset already
// handles.
constexpr double kCubeTexelBias = 0.5;
} // namespace

ProjectionFit CubeMapProjection::fit(LightState& light, const PlanContext& context,
                                     const FrustumFitOptions& options) const {
    LightShadowFrame& plan = light.frame;
    const engine::LightInstance& placed = context.scene.lightInstances[light.slot];
    plan.pointViews = fitPointLight(placed, context.scene.lights[placed.light], context.bounds, options);
    bool empty = true;
    for (const LightView& face : plan.pointViews.faces) empty = empty && face.empty;
    return {plan.pointViews.valid, empty, plan.pointViews.invalidReason};
}

void CubeMapProjection::decideCache(LightState& light, const engine::Scene& scene, std::uint64_t sceneGeneration,
                                    bool cacheMaps) const {
    light.frame.mapKey = withDepthSettings(mapCacheKey(light, scene, sceneGeneration), light.settings);
    light.frame.cacheHit = cacheMaps && light.frame.mapKey == light.renderedKey;
}

std::vector<MapLayer> CubeMapProjection::layers(const LightState& light) const {
    // A face that sees no receiver is cleared (lookups there must read "far") but draws
    // nothing; the last face records the map's key.
    std::vector<MapLayer> faces;
    for (int face = 0; face < engine::kCubeFaces; ++face) {
        const LightView& view = light.frame.pointViews.faces[face];
        faces.push_back({face, view.viewProjection(), !view.empty, -1, face == 5 ? light.frame.mapKey : 0});
    }
    return faces;
}

bool CubeMapProjection::packLookup(const LightState& light, const LookupContext& context, ShadowBlock& block,
                                   HookGlsl::Lookup& lookup) const {
    const glm::dvec3 lightPosition = context.scene.lightInstances[light.slot].position();
    const glm::dvec4 eyeLight = context.view * glm::dvec4(lightPosition, 1.0);
    // The lookup rotates eye directions back to world (V^-1's columns) and needs the light
    // in eye space: what the GPU gets of them must be finite.
    if (!isFinite(glm::mat4(glm::dmat4(context.view[0], context.view[1], context.view[2], eyeLight)))) return false;
    const PointLightViews& views = light.frame.pointViews;
    block.lightInEye[light.slot] = glm::vec4(glm::vec3(eyeLight), 1.0f);
    block.pointFar[light.slot].z = static_cast<float>(views.nearPlane);
    // 0 stands for an infinite far plane (GLSL has no infinity to pass).
    block.pointFar[light.slot].x = std::isinf(views.farPlane) ? 0.0f : static_cast<float>(views.farPlane);
    // y: the bias in face widths (a 90-degree face spans 2 * distance over resolution texels).
    block.pointFar[light.slot].y = static_cast<float>(kCubeTexelBias * 2.0 / light.settings.resolution);
    block.softLayers[light.slot * kMaxCascades] = softCubeLayer(views, light);
    block.texelWidths[light.slot] = glm::vec4(cubeTexelWidthPerDepth(light.settings.resolution), 0.0f, 0.0f, 0.0f);
    lookup.cube = true;
    return true;
}

void CubeMapProjection::addStats(const LightState& light, nlohmann::json& stats) const {
    stats["near"] = light.frame.pointViews.nearPlane;
    stats["far"] = light.frame.pointViews.farPlane;
}

void CubeMapProjection::describe(const LightState& light, engine::ShadowView& out) const {
    for (const LightView& face : light.frame.pointViews.faces)
        out.layers.push_back({face.lightToWorld, face.projection, !face.empty, !light.frame.cacheHit});
    out.nearPlane = light.frame.pointViews.nearPlane;
    out.farPlane = light.frame.pointViews.farPlane;
}

} // namespace shadowmap
