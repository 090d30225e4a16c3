#pragma once
// Small, deterministic edits of a loaded scene, for tools and benchmarks: orbiting a node
// (a light) about the scene's vertical axis, and adding a key light to a model that has
// none (e.g. Debian's 2CylinderEngine.glb).
#include "engine/scene/Scene.h"

namespace engine {

// Rotates node `node`'s world placement by `angle` radians about the world Y axis through
// `center` (its orientation turns with it), then recomposes the world transforms.
void orbitNode(Scene& scene, int node, const glm::dvec3& center, double angle);

// Rotates an eye -> world transform (V) the same way (for --orbit-camera).
glm::dmat4 orbitTransform(const glm::dmat4& transform, const glm::dvec3& center, double angle);

// Where a key light stands, seen from the framing view (Framing.h): azimuth turns from the
// camera's side of the model toward the camera's right (negative: its left), elevation
// rises from the horizon, both in degrees. The default, 70 to the side and 45 up, throws the
// shadow beside the model where the framing camera sees it: a light near the camera's
// azimuth (6 degrees off) hid the directional light's shadow behind the model for 21 of the
// 22 assimp test models the test below checks, and three-point lighting's 45 degrees still
// for 15 (AssimpModels.TheKeyLightsShadowFallsOnGroundTheFramingCameraSees).
struct KeyLightAngles {
    double azimuthDegrees = 70.0;    // [-180, 180]
    double elevationDegrees = 45.0;  // (0, 90]
};

// Adds a light named `name` of `type`, placed from the scene's bounds: at `angles` from their
// centre at twice their radius, aimed at the centre; spot cone wide enough to cover the
// bounds; intensity giving an irradiance of 2 at the centre. Returns the new node and
// recomposes the world transforms.
int addKeyLight(Scene& scene, Light::Type type, const std::string& name = "key_light", KeyLightAngles angles = {});

// The unit direction from the bounds' centre toward a key light at `angles`.
glm::dvec3 keyLightDirection(const KeyLightAngles& angles);

// Adds a ground that receives shadows but casts none: a square in the world XZ plane (glTF's
// up is +Y) just below the bottom of the scene's bounds, centred under them, 4 radii wide,
// in a grey material of its own, so an isolated model shows where its shadow falls. Call it
// after addKeyLight: the light is placed from the model's bounds, not the ground's. Returns
// the new node and recomposes the world transforms.
int addGround(Scene& scene, const std::string& name = "ground");

} // namespace engine
