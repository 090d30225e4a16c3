#pragma once
// The scenes shadowmap-stress renders, generated in code: a closed floor slab with closed
// boxes on it (two standing on the floor, in contact), one box hovering, a thin plank (3 cm
// at unit scale), one light of a chosen type and a camera that sees the shadows.
//
// Every length is multiplied by `scale` and everything (geometry, light, camera) is then
// translated by `offset`, through the nodes' transforms, as a glTF scene far from the
// origin is: mesh positions stay small floats, the placement is a double matrix.
//
// Layouts (the special cases that break a naive shadow map):
//   Standard           light above the floor centre at `elevationDeg` over the floor
//                      (spot 14 units away, point 8, directional from that direction)
//   LightInsideBox     a closed hollow shell (2 units, hovering 0.4 over the floor) with the
//                      light at its centre: every receiver outside it must be in shadow
//   LightOnSurface     spot: apex on the tower's top face; point: on the floor's top face
//                      (the floor then casts but does not receive: it holds the light,
//                      N.L = 0 on it, and rounding alone would decide its pixels)
//   CameraAtLight      the standard spot, seen from its own apex (nothing visible is
//                      shadowed: any shadow is acne)
//   LightStraightDown  the light's direction is (0,-1,0), parallel to the usual up vector;
//                      the boxes are turned 3 degrees so no face is exactly edge-on
//   MaskedFence        the floor and nothing on it but a fence 6 x 2 units at its centre,
//                      facing the light's azimuth, lit as Standard: ONE double-sided quad with
//                      alphaMode MASK (cutoff 0.5) and a 96 x 32 binary-alpha texture (slats 3
//                      texels wide with 3-texel gaps, two rails; sampler LINEAR /
//                      LINEAR_MIPMAP_LINEAR / CLAMP_TO_EDGE), as content/scenes/masked_fence.gltf
//   OpaqueFence        its twin: the same fence as one opaque double-sided quad per slat and
//                      per rail on the texel boundaries (where the 0.5 iso-line of the
//                      bilinearly filtered binary alpha lies, but for half-texel corner rounding)
#include "engine/render/Frame.h"
#include "engine/scene/Scene.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace stress {

enum class LightKind { Spot, Directional, Point };
enum class Layout { Standard, LightInsideBox, LightOnSurface, CameraAtLight, LightStraightDown, MaskedFence, OpaqueFence };

const char* toString(LightKind kind);
const char* toString(Layout layout);
engine::Light::Type lightType(LightKind kind);

struct SceneSpec {
    LightKind light = LightKind::Spot;
    Layout layout = Layout::Standard;
    double elevationDeg = 45.0;  // Standard layout: light direction over the floor
    double scale = 1.0;          // every length times this
    glm::dvec3 offset{0.0};      // then everything translated by this (world units)
    // The offset baked into the mesh positions (float, identity nodes), as a glTF whose
    // vertices were exported in world space holds it, instead of a node translation.
    bool bakeOffset = false;
    // Every mesh skinned to one joint node that carries the placement (inverse bind matrix
    // the identity, weight 1), its own node the identity: posed on the CPU (Deform.h), as an
    // exported character is, instead of placed by its node's matrix. Not with bakeOffset.
    bool skinned = false;
    // The light's extras.shadow (variant, depth_format, resolution, ...). The two keys
    // below are added by the builder in world units, so they scale with the scene.
    nlohmann::json shadow = nlohmann::json::object();
    // Spot and point: force the light's near/far ratio. far_plane is set just beyond the
    // farthest scene corner from the light and near_plane = nearOverFar * far_plane;
    // infiniteFar: far_plane "infinite", near_plane = nearOverFar * that corner distance.
    std::optional<double> nearOverFar;
    bool infiniteFar = false;
};

struct StressScene {
    engine::Scene scene;          // world transforms up to date; light slot 0
    engine::FrameCamera camera;
    std::string lightName = "light";
    double farthestCorner = 0.0;  // distance from the light to the farthest scene corner
};

StressScene buildStressScene(const SceneSpec& spec, int width, int height);

} // namespace stress
