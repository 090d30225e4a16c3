#pragma once
// Light view (L) and projection (P_light) for each light type, fitted in double to the
// world bounds of shadow casters and receivers so depth precision is spent where geometry
// is. No GL: the plugin turns these into passes and texgen.
//
// Conventions (as Texgen.h): L = light -> world, rigid (rotation + position,
// any node scale dropped), the light looks down its -Z; P_light uses the OpenGL clip
// convention (z_ndc in [-1,1]), so S * P_light * L^-1 (see Texgen.h) maps what the light
// sees to [0,1]^3. nearPlane/farPlane are distances along the light's -Z.
//
// Fitting:
//  - spot: perspective, fovy = 2 * outerConeAngle (clamped to < 180 deg), aspect 1. Every
//    box is clipped to the light's square pyramid first, so geometry outside the cone does
//    not stretch the range. far = farthest receiver depth inside the pyramid (a caster
//    beyond every receiver cannot shadow one), clamped to range when range > 0;
//    near = nearest caster or receiver depth inside the pyramid, but at least
//    far * minNearFraction so far/near stays bounded.
//  - directional: orthographic. x/y fitted to the receivers; z from the farthest receiver
//    to the nearest-to-the-light point of any caster whose x/y footprint overlaps that
//    rectangle. The light's position is ignored: L sits at the centre of the fitted box's
//    face toward the light, so its numbers are those of the scene, not of the node.
//  - point: six 90 deg faces in GL cube-map order (+X,-X,+Y,-Y,+Z,-Z) with the standard
//    cube-map up vectors, axis-aligned in world space (node rotation ignored), so that a
//    samplerCubeShadow lookup with direction (world - lightPos) reads the texel the face
//    wrote. One near/far shared by all faces (the shader computes the reference depth from
//    the major axis, see cubeShadowReferenceDepth), fitted over all faces.
#include "engine/graph/TextureDesc.h"
#include "engine/scene/Aabb.h"
#include "engine/scene/Scene.h"

#include <array>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace shadowmap {

// World-space boxes the fit considers, one per mesh instance (tighter than one union box).
// Empty and non-finite boxes are ignored.
struct ShadowBounds {
    std::vector<engine::Aabb> casters;
    std::vector<engine::Aabb> receivers;

    // From Scene::meshInstances (their castShadows / receiveShadows flags).
    static ShadowBounds fromScene(const engine::Scene& scene);
};

struct FrustumFitOptions {
    double minNearFraction = 1e-4;  // near >= far * minNearFraction
    // Spot and point (ShadowSettings near_plane / far_plane, for scenes whose range breaks the
    // fit, see tools/shadowmap-stress): > 0 replaces the
    // fitted near / far; farPlane may be +infinity (an infinite perspective). With
    // reversedZ and no farPlane, the far plane is infinite (see finishPerspectiveDepth).
    double nearPlane = 0.0;
    double farPlane = 0.0;
    // Reversed Z: P_light maps near -> 1 and far -> 0 in a [0,1] clip range, for
    // glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE); see LightView::reversedZ.
    bool reversedZ = false;
    double depthMargin = 1e-3;      // [near, far] widened by this fraction of its length
    double extentMargin = 1e-3;     // directional x/y box widened by this fraction
    double maxSpotHalfAngle = 1.5533430342749532;  // 89 deg: perspective needs < 90
};

struct LightView {
    glm::dmat4 lightToWorld{1.0};  // L
    glm::dmat4 projection{1.0};    // P_light
    double nearPlane = 0.0, farPlane = 0.0;  // farPlane +infinity: infinite perspective
    bool valid = false;  // false: degenerate light, see invalidReason; never NaN
    std::string invalidReason;
    std::string clampWarning;  // a light parameter was clamped to stay usable (say so)
    double nearestReceiver = 0.0;  // perspective: depth of the nearest receiver inside
    bool empty = true;  // no receiver inside the frustum: the pass can be skipped
    // false: OpenGL clip convention (z in [-w, w], window depth 0 at near, 1 at far).
    // true: [0,1] clip depth with near at 1 and far at 0 (glClipControl ZERO_TO_ONE), and
    // S leaves r unscaled (scaleBiasZeroToOne): window depth = r/q directly.
    bool reversedZ = false;
    // A light-space perspective map (math/LispsmWarp.h): the projection warps along L's y,
    // with near and far (nearPlane, farPlane) along that axis, not along the light.
    bool warped = false;
    glm::dvec2 warpFitScale{0.0};  // warped: O's scales of x and y after the warp (O00, O11)

    glm::dmat4 worldToLight() const;    // L^-1 (rigid inverse)
    glm::dmat4 viewProjection() const;  // P_light * L^-1
    glm::dmat4 texgenPlanes() const;    // Epo = S * P_light * L^-1 (S for the convention)
};

// The window-depth change across one texel of a surface at 45 degrees to the light's axis
// (the polygon offset's slope m for slope 1), with `resolution` texels per side:
// orthographic: texel width / (far - near), the same everywhere; perspective: at the
// nearest receiver (largest there), texel width(d) * |d window depth / d distance|(d);
// warped: at the body's near end along the warp axis, the wider of its two texel widths.
double windowDepthPerTexel(const LightView& view, int resolution);

// GL cube-map face order (GL_TEXTURE_CUBE_MAP_POSITIVE_X + face).
enum CubeFace : int { PositiveX = 0, NegativeX, PositiveY, NegativeY, PositiveZ, NegativeZ };
glm::dvec3 cubeFaceDirection(int face);  // the face's viewing direction (major axis)
glm::dvec3 cubeFaceUp(int face);         // its up vector (OpenGL cube-map table)

struct PointLightViews {
    std::array<LightView, engine::kCubeFaces> faces;          // faces[f].empty: nothing to receive in face f
    double nearPlane = 0.0, farPlane = 0.0;  // shared by all faces (far may be +infinity)
    bool reversedZ = false;                  // as LightView::reversedZ, for all faces
    bool valid = false;
    std::string invalidReason;

    // Whether the box intersects face f's frustum (conservative); false for invalid lights.
    bool faceSeesBox(int face, const engine::Aabb& worldBox) const;
};

// The r a samplerCubeShadow lookup must compare for the point lightToPoint = world - light
// position (what the face that holds the texel wrote): S applied to the depth of the face
// perspective at distance max(|x|,|y|,|z|) along the major axis.
// reversedZ: the window depth of the reversed [0,1] projection instead (near 1, far 0).
double cubeShadowReferenceDepth(const glm::dvec3& lightToPoint, double nearPlane, double farPlane,
                                bool reversedZ = false);

// The light's -Z in world space (unit) from its node matrix, in `direction`; a reason when it
// is not usable (not finite, zero length), else an empty string.
std::string directionProblem(const engine::LightInstance& instance, glm::dvec3& direction);
// A view that says why the light has no shadow (valid false).
LightView invalidView(std::string reason);
// Whether every entry is finite; whether a box is non-empty with finite corners (the fits
// ignore any other box).
bool isFiniteMatrix(const glm::dmat4& m);
bool usableBounds(const engine::Aabb& box);

// A rigid L (columns x, y, z = -direction, position) with an up vector that is robust for
// every direction: the world axis least parallel to it. Direction need not be unit length.
glm::dmat4 lightToWorldFromDirection(const glm::dvec3& position, const glm::dvec3& direction);

// An orthographic view of a box given in a light frame: `frame` is a rigid L whose -Z is the
// light's direction; the box is centre.x +- half.x, centre.y +- half.y, zBottom .. zTop in
// its coordinates (zTop toward the light). The view's L sits at the centre of the box's face
// toward the light, near 0, far zTop - zBottom. Used by the cascades (CascadeFit.h); half
// extents are passed as such so that a stable cascade's projection is the same number
// wherever its centre is.
LightView orthographicViewOfBox(const glm::dmat4& frame, const glm::dvec2& centre, const glm::dvec2& half,
                                double zBottom, double zTop, bool reversedZ);

LightView fitSpotLight(const engine::LightInstance& instance, const engine::Light& light,
                       const ShadowBounds& bounds, const FrustumFitOptions& options = {});
LightView fitDirectionalLight(const engine::LightInstance& instance, const engine::Light& light,
                              const ShadowBounds& bounds, const FrustumFitOptions& options = {});
PointLightViews fitPointLight(const engine::LightInstance& instance, const engine::Light& light,
                              const ShadowBounds& bounds, const FrustumFitOptions& options = {});

}  // namespace shadowmap
