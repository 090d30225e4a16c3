#pragma once
// The engine's own scene graph: plain data, filled by the glTF loader (or by tests), read
// by the renderer and the plugins. Transforms: M (object -> world) per
// node, composed in double. Cameras look down their node's -Z, lights shine down -Z.
#include "engine/scene/Aabb.h"
#include "engine/scene/Animation.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace engine {

struct DeformedMesh;

// A morph target of a primitive: per-vertex offsets added, weighted, to the base shape
// (glTF 2.0 section 3.7.2.2). `normals` is empty when the target moves no normal.
struct MorphTarget {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
};

// Triangles only: the loader converts strips and fans; points and lines are dropped with
// a warning. Positions are in object space (float, as glTF stores them).
struct Primitive {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;    // always filled: generated (area-weighted) when absent
    std::vector<glm::vec2> texcoords;   // empty when the primitive has no TEXCOORD_0
    std::vector<glm::vec2> texcoords1;  // empty when the primitive has no TEXCOORD_1
    // COLOR_0 as linear RGBA (vec3 colors get alpha 1); empty when absent (white).
    std::vector<glm::vec4> colors;
    // JOINTS_0 / WEIGHTS_0 (empty when absent): four joints per vertex, as indices into the
    // node's Skin::joints, and their weights, normalized by the loader to sum to 1.
    std::vector<glm::uvec4> joints;
    std::vector<glm::vec4> weights;
    std::vector<MorphTarget> targets;    // the same count in every primitive of a mesh
    std::vector<std::uint32_t> indices;  // triangle list; 3 per triangle
    int material = -1;                   // index into Scene::materials, -1 = default material
    // KHR_lights_shadows on the primitive (default true). They combine with the node's
    // extras: a primitive casts only if both say so, and likewise for receiving.
    bool castShadows = true;
    bool receiveShadows = true;
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
    Aabb bounds;  // object space, union of the primitives (the base shape)
    std::vector<float> weights;  // default morph target weights (one per target; zeros if unset)
    std::size_t triangleCount() const;
};

struct Image {
    std::string name;
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba8;  // width*height*4, row 0 = top (as decoded)
};

enum class AlphaMode { Opaque, Mask, Blend };

// A glTF sampler, as the OpenGL enumerants glTF itself uses. An undefined filter takes the
// engine's choice (trilinear minification, linear magnification).
struct Sampler {
    int magFilter = 0x2601;  // GL_LINEAR
    int minFilter = 0x2703;  // GL_LINEAR_MIPMAP_LINEAR
    int wrapS = 0x2901;      // GL_REPEAT
    int wrapT = 0x2901;
    bool operator==(const Sampler&) const = default;
};

// KHR_texture_transform: uv' = T(offset) * R(rotation) * S(scale) * uv. The rotation turns
// the UVs counter-clockwise (the image clockwise): u' = cos*u + sin*v, v' = -sin*u + cos*v,
// as the extension's example (the lower-left quadrant turned 90 degrees) requires.
struct UvTransform {
    glm::vec2 offset{0.0f};
    float rotation = 0.0f;  // radians
    glm::vec2 scale{1.0f};
    // The 3x3 affine matrix (column-major, as GLSL takes it) that maps (u, v, 1).
    glm::mat3 matrix() const;
    glm::vec2 apply(const glm::vec2& uv) const { return glm::vec2(matrix() * glm::vec3(uv, 1.0f)); }
    bool operator==(const UvTransform&) const = default;
};

// A material's reference to a texture: glTF textureInfo with its texture's image and sampler.
struct TextureRef {
    int image = -1;     // index into Scene::images, -1 = none
    Sampler sampler;
    int texCoord = 0;   // which TEXCOORD_n set (KHR_texture_transform's texCoord applied)
    UvTransform transform;
    bool present() const { return image >= 0; }
};

struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};
    TextureRef baseColorTexture;
    float metallicFactor = 1.0f;
    float roughnessFactor = 1.0f;
    glm::vec3 emissiveFactor{0.0f};
    bool doubleSided = false;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    // BLEND materials cast shadow where their alpha reaches this (material extras
    // "shadow_alpha_cutoff", default 0.5): a half-transparent pane blocks light as a mask
    // would. 0 casts everywhere (as opaque), above 1 casts nothing.
    float blendShadowCutoff = 0.5f;
};

// The alpha below which a caster made of `material` lets light through: MASK its
// alphaCutoff, BLEND its blendShadowCutoff, OPAQUE (and a cutoff of 0) none: < 0.
float shadowAlphaCutoff(const Material& material);
// True when shadow casting must test alpha (shadowAlphaCutoff >= 0): such a caster is open,
// whatever its geometry, and costs the depth passes a texture lookup.
inline bool castsAlphaTested(const Material& material) { return shadowAlphaCutoff(material) >= 0.0f; }

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
    // KHR_lights_shadows "castShadows" on the light (default true): false means no shadow
    // from this light, whatever its extras say.
    bool castShadows = true;
    // The light object's "extras" (e.g. {"shadow":{...}}), kept for plugins to interpret.
    nlohmann::json extras = nlohmann::json::object();
};

// glTF skin: the nodes whose world transforms pose a skinned mesh, with each joint's inverse
// bind matrix (identity when the file gives none). A skinned vertex's world position is
// sum_i w_i * world(joints[j_i]) * inverseBindMatrices[j_i] * p; the mesh node's own
// transform is not applied (glTF 2.0 section 3.7.3).
struct Skin {
    std::string name;
    std::vector<int> joints;  // valid node indices, at least one
    std::vector<glm::dmat4> inverseBindMatrices;  // one per joint
};

struct Node {
    std::string name;
    int parent = -1;
    std::vector<int> children;
    glm::dmat4 local{1.0};  // from TRS or matrix
    // The TRS the file gives (identity for a node given by matrix, which glTF forbids
    // animating). Animation writes these and sets local = trsMatrix().
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};  // unit, (w, x, y, z) as glm stores it
    glm::dvec3 scale{1.0};
    // Morph target weights: the node's own (glTF node.weights) or an animation's; empty =
    // the mesh's defaults.
    std::vector<float> weights;
    int skin = -1;  // index into Scene::skins, -1 = none (only with a mesh)
    glm::dmat4 trsMatrix() const;  // T * R * S
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
    // Equal across two Scene::updateWorldTransforms() calls exactly when the instance's
    // world matrix did not change between them; a changed instance gets a value the scene
    // never used before. Caches of what an instance looks like (a light's shadow map) key
    // on it, so they see a caster move and keep their contents while it stands still.
    // A deformed instance's revision also changes when its vertices do.
    std::uint64_t revision = 0;
    // Skinned or morphed: the vertices as posed now (Deform.h), shared by every pass and by
    // the truth; world is then the frame they are given in (identity for a skinned mesh).
    // Null for an instance drawn from its mesh as loaded.
    std::shared_ptr<const DeformedMesh> deformed;
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
    std::vector<Animation> animations;
    std::vector<Skin> skins;

    // Filled by updateWorldTransforms(), in depth-first order from the roots.
    std::vector<MeshInstance> meshInstances;
    std::vector<LightInstance> lightInstances;
    std::vector<CameraInstance> cameraInstances;
    Aabb worldBounds;  // all mesh instances
    std::uint64_t lastInstanceRevision = 0;  // the newest MeshInstance::revision handed out

    // Composes node.world = parent.world * node.local (double) from the roots and rebuilds
    // the instance lists and bounds. Call after changing any node's local transform (for
    // instance after poseAnimation).
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
