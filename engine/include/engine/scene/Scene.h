#pragma once
// The engine's own scene graph: plain data, filled by the glTF loader (or by tests), read
// by the renderer and the plugins. Transforms follow DESIGN.md: M (object -> world) per
// node, composed in double. Cameras look down their node's -Z, lights shine down -Z.
#include "engine/scene/Aabb.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace engine {

// Triangles only: the loader converts strips and fans; points and lines are dropped with
// a warning. Positions are in object space (float, as glTF stores them).
struct Primitive {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;    // always filled: generated (area-weighted) when absent
    std::vector<glm::vec2> texcoords;  // empty when the primitive has no TEXCOORD_0
    std::vector<std::uint32_t> indices;  // triangle list; 3 per triangle
    int material = -1;                   // index into Scene::materials, -1 = default material
    Aabb bounds;                         // object space
    std::size_t triangleCount() const { return indices.size() / 3; }
};

struct Mesh {
    std::string name;
    std::vector<Primitive> primitives;
    // Closed: after welding vertices by position, every edge is shared by exactly two
    // triangles that traverse it in opposite directions (a watertight, consistently wound
    // surface). The backface shadow variant is only valid for closed meshes.
    bool closed = false;
    Aabb bounds;  // object space, union of the primitives
    std::size_t triangleCount() const;
};

struct Image {
    std::string name;
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba8;  // width*height*4, row 0 = top (as decoded)
};

enum class AlphaMode { Opaque, Mask, Blend };

struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};
    int baseColorImage = -1;  // index into Scene::images, -1 = none
    float metallicFactor = 1.0f;
    float roughnessFactor = 1.0f;
    glm::vec3 emissiveFactor{0.0f};
    bool doubleSided = false;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
};

struct Camera {
    enum class Type { Perspective, Orthographic };
    std::string name;
    Type type = Type::Perspective;
    double yfov = 0.8;         // radians (perspective)
    double aspectRatio = 0.0;  // 0 = take it from the viewport
    double znear = 0.1;
    double zfar = 0.0;         // 0 = infinite (perspective only)
    double xmag = 1.0, ymag = 1.0;  // orthographic half extents
};

struct Light {
    enum class Type { Directional, Spot, Point };
    std::string name;
    Type type = Type::Point;
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    double range = 0.0;  // 0 = infinite (glTF: undefined range)
    double innerConeAngle = 0.0;               // radians, spot only
    double outerConeAngle = 0.78539816339744831;  // pi/4, spot only
    // The light object's "extras" (e.g. {"shadow":{...}}), kept for plugins to interpret.
    nlohmann::json extras = nlohmann::json::object();
};

struct Node {
    std::string name;
    int parent = -1;
    std::vector<int> children;
    glm::dmat4 local{1.0};  // from TRS or matrix
    glm::dmat4 world{1.0};  // filled by Scene::updateWorldTransforms
    int mesh = -1, camera = -1, light = -1;
    // Node extras "cast_shadows" / "receive_shadows"; inherited by nothing (per node).
    bool castShadows = true;
    bool receiveShadows = true;
};

// A mesh placed in the world by a node, with everything a pass needs to cull and draw it.
struct MeshInstance {
    int node = -1;
    int mesh = -1;
    glm::dmat4 world{1.0};  // M
    Aabb worldBounds;
    bool castShadows = true;
    bool receiveShadows = true;
};

// A light or camera placed by a node: world = L (light -> world) or V (eye -> world).
struct LightInstance {
    int node = -1;
    int light = -1;
    glm::dmat4 world{1.0};
    glm::dvec3 position() const { return glm::dvec3(world[3]); }
    glm::dvec3 direction() const { return glm::normalize(-glm::dvec3(world[2])); }
};
struct CameraInstance {
    int node = -1;
    int camera = -1;
    glm::dmat4 world{1.0};
};

struct Scene {
    std::string sourcePath;  // for messages
    std::vector<Node> nodes;
    std::vector<int> roots;  // nodes of the displayed glTF scene
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Image> images;
    std::vector<Camera> cameras;
    std::vector<Light> lights;

    // Filled by updateWorldTransforms(), in depth-first order from the roots.
    std::vector<MeshInstance> meshInstances;
    std::vector<LightInstance> lightInstances;
    std::vector<CameraInstance> cameraInstances;
    Aabb worldBounds;  // all mesh instances

    // Composes node.world = parent.world * node.local (double) from the roots and rebuilds
    // the instance lists and bounds. Call after changing any node's local transform.
    void updateWorldTransforms();

    // Lookups by name; -1 when absent.
    int findLightInstance(const std::string& name) const;
    int findCameraInstance(const std::string& name) const;
};

// Welds vertices by exact position and checks that every undirected edge is used by
// exactly two triangles with opposite directions. Degenerate triangles are ignored.
bool isClosedSurface(const Mesh& mesh);

// Area-weighted vertex normals for a triangle list (used when a primitive has none).
std::vector<glm::vec3> generateNormals(const std::vector<glm::vec3>& positions,
                                       const std::vector<std::uint32_t>& indices);

} // namespace engine
