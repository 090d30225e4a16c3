#pragma once
// The scene's meshes and material textures on the GPU, uploaded once per scene and shared by
// every pass that draws geometry (the lit pass, the shadow plugin's depth passes).
#include "engine/gl/Buffer.h"
#include "engine/gl/Texture.h"
#include "engine/gl/VertexArray.h"
#include "engine/render/MaterialTextures.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

namespace engine {

struct Scene;
struct Mesh;
struct MeshInstance;
struct DeformedMesh;

// Vertex attribute locations every engine and plugin shader uses.
constexpr unsigned kAttribPosition = 0;
constexpr unsigned kAttribNormal = 1;
constexpr unsigned kAttribTexcoord = 2;   // TEXCOORD_0
constexpr unsigned kAttribTexcoord1 = 3;  // TEXCOORD_1
constexpr unsigned kAttribColor = 4;      // COLOR_0
constexpr unsigned kAttribTangent = 5;    // TANGENT

class SceneGpu {
public:
    struct Primitive {
        gl::Buffer positions, normals, tangents, texcoords, texcoords1, colors, indices;
        gl::VertexArray vertexArray;
        std::int32_t indexCount = 0;
        int material = -1;
        // An absent attribute reads the constant applyMaterial() sets (MaterialShading.h).
        bool hasTexcoords = false, hasTexcoords1 = false, hasColors = false;
        bool hasTangents = false;  // normal mapping needs them
        // The source primitive's KHR_lights_shadows flags.
        bool castShadows = true, receiveShadows = true;
    };

    explicit SceneGpu(const Scene& scene);

    // Uploads the posed vertices of the scene's deformed instances (skinned or morphed,
    // MeshInstance::deformed) that changed since the last call, and drops those that are
    // gone. Call after Scene::updateWorldTransforms, before drawing (Renderer does).
    void updateDeformed(const Scene& scene);

    // What to draw for an instance: its posed copy when deformed, else its mesh's.
    const std::vector<Primitive>& primitives(const MeshInstance& instance) const;
    // A mesh's primitives as loaded (materials, counts; not for drawing an instance).
    const std::vector<Primitive>& meshPrimitives(int mesh) const { return meshes_.at(mesh); }
    // The model matrix to draw an instance's primitives with: M times the translation to the
    // mesh's bounds centre (a deformed instance: its pose's origin). Vertices are uploaded
    // relative to that centre (subtracted in double), so a mesh whose vertices sit 10^6
    // from the origin keeps its float precision; every drawer must use this, not
    // MeshInstance::world alone.
    glm::dmat4 modelMatrix(const MeshInstance& instance) const;
    // Binds the primitive's vertex array and draws it; returns its triangle count.
    std::uint64_t draw(const Primitive& primitive) const;
    // Draws `count` indices from `first` of another triangle list into the primitive's
    // vertices (a simplified level of it, say), with its vertex arrays: whatever is per vertex
    // (a deformed instance's pose, UVs) is the primitive's. Returns the triangles drawn.
    std::uint64_t drawIndices(const Primitive& primitive, const gl::Buffer& indices, std::uint32_t first,
                              std::uint32_t count) const;
    // The material's texture of that kind (mipmapped, sRGB-decoded where isSrgb says so,
    // its glTF sampler's filters and wrap modes set on it), or 0 when it has none.
    unsigned materialTexture(int material, MaterialTexture texture) const;

private:
    // A deformed instance's own vertex buffers (positions, normals and tangents updatable;
    // the rest copied from its mesh), by node.
    struct DeformedInstance {
        int mesh = -1;
        std::shared_ptr<const DeformedMesh> pose;  // what was uploaded
        std::vector<Primitive> primitives;
    };
    static void upload(DeformedInstance& gpu, const Mesh& mesh, const DeformedMesh& pose);

    std::vector<std::vector<Primitive>> meshes_;
    std::unordered_map<int, DeformedInstance> deformed_;
    std::vector<glm::dvec3> meshOrigins_;      // per mesh: its bounds' centre
    // One texture per distinct (image, sampler, sRGB or not) the materials use: the
    // sampler's state lives on the texture, so binding it is all a pass does (no sampler
    // object left bound to a unit that another pass uses for a depth map).
    std::vector<gl::Texture> textures_;
    // Per material and MaterialTexture: index into textures_, or -1.
    std::vector<std::array<int, kMaterialTextureCount>> materialTextures_;
};

} // namespace engine
