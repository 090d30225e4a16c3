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

// Adds a light named `name` of `type`, placed from the scene's bounds: above and to the
// side of their centre at twice their radius, aimed at the centre; spot cone wide enough
// to cover the bounds; intensity giving an irradiance of 2 at the centre. Returns
// the new node and recomposes the world transforms.
int addKeyLight(Scene& scene, Light::Type type, const std::string& name = "key_light");

// Adds a ground that receives shadows but casts none: a square in the world XZ plane (glTF's
// up is +Y) just below the bottom of the scene's bounds, centred under them, 4 radii wide,
// in a grey material of its own, so an isolated model shows where its shadow falls. Call it
// after addKeyLight: the light is placed from the model's bounds, not the ground's. Returns
// the new node and recomposes the world transforms.
int addGround(Scene& scene, const std::string& name = "ground");

} // namespace engine
