#include "engine/render/SceneGpu.h"

#include "engine/scene/Deform.h"
#include "engine/scene/Scene.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <tuple>

namespace engine {

namespace {

template <typename T>
gl::Buffer uploadArray(const std::vector<T>& data, GLbitfield storageFlags = 0) {
    return gl::Buffer::create(data.size() * sizeof(T), data.data(), storageFlags);
}

template <typename T>
void updateArray(gl::Buffer& buffer, const std::vector<T>& data) {
    buffer.update(0, data.size() * sizeof(T), data.data());
}

std::vector<glm::vec3> relativeTo(const std::vector<glm::vec3>& positions, const glm::dvec3& origin) {
    std::vector<glm::vec3> relative(positions.size());
    for (std::size_t i = 0; i < relative.size(); ++i) relative[i] = glm::vec3(glm::dvec3(positions[i]) - origin);
    return relative;
}

// The source primitive's buffers with the given positions (relative to the draw's origin),
// normals and tangents; `storageFlags` lets those three be updated (deformed instances).
SceneGpu::Primitive uploadPrimitive(const engine::Primitive& source, const std::vector<glm::vec3>& positions,
                                    const std::vector<glm::vec3>& normals, const std::vector<glm::vec4>& tangents,
                                    GLbitfield storageFlags = 0) {
    SceneGpu::Primitive gpu;
    gpu.positions = uploadArray(positions, storageFlags);
    gpu.normals = uploadArray(normals, storageFlags);
    gpu.indices = uploadArray(source.indices);
    gpu.indexCount = static_cast<std::int32_t>(source.indices.size());
    gpu.material = source.material;
    gpu.vertexArray = gl::VertexArray::create();
    gpu.vertexArray.attribute(kAttribPosition, gpu.positions, 3, GL_FLOAT, sizeof(glm::vec3));
    gpu.vertexArray.attribute(kAttribNormal, gpu.normals, 3, GL_FLOAT, sizeof(glm::vec3));
    gpu.hasTangents = !tangents.empty();
    if (gpu.hasTangents) {
        gpu.tangents = uploadArray(tangents, storageFlags);
        gpu.vertexArray.attribute(kAttribTangent, gpu.tangents, 4, GL_FLOAT, sizeof(glm::vec4));
    }
    gpu.hasTexcoords = !source.texcoords.empty();
    if (gpu.hasTexcoords) {
        gpu.texcoords = uploadArray(source.texcoords);
        gpu.vertexArray.attribute(kAttribTexcoord, gpu.texcoords, 2, GL_FLOAT, sizeof(glm::vec2));
    }
    gpu.hasTexcoords1 = !source.texcoords1.empty();
    if (gpu.hasTexcoords1) {
        gpu.texcoords1 = uploadArray(source.texcoords1);
        gpu.vertexArray.attribute(kAttribTexcoord1, gpu.texcoords1, 2, GL_FLOAT, sizeof(glm::vec2));
    }
    gpu.hasColors = !source.colors.empty();
    if (gpu.hasColors) {
        gpu.colors = uploadArray(source.colors);
        gpu.vertexArray.attribute(kAttribColor, gpu.colors, 4, GL_FLOAT, sizeof(glm::vec4));
    }
    gpu.castShadows = source.castShadows;
    gpu.receiveShadows = source.receiveShadows;
    gpu.vertexArray.elementBuffer(gpu.indices);
    return gpu;
}

gl::Texture uploadImage(const Image& image, const Sampler& sampler, bool srgb) {
    const int levels =
        1 + static_cast<int>(std::floor(std::log2(std::max(image.width, image.height))));
    gl::Texture texture =
        gl::Texture::create2D(srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, image.width, image.height, levels);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA,
                        GL_UNSIGNED_BYTE, image.rgba8.data());
    glGenerateTextureMipmap(texture.id());
    texture.setParameter(GL_TEXTURE_MIN_FILTER, sampler.minFilter);
    texture.setParameter(GL_TEXTURE_MAG_FILTER, sampler.magFilter);
    texture.setParameter(GL_TEXTURE_WRAP_S, sampler.wrapS);
    texture.setParameter(GL_TEXTURE_WRAP_T, sampler.wrapT);
    return texture;
}

} // namespace

SceneGpu::SceneGpu(const Scene& scene) {
    meshes_.reserve(scene.meshes.size());
    for (const Mesh& mesh : scene.meshes) {
        const glm::dvec3 origin = mesh.bounds.empty() ? glm::dvec3(0.0) : mesh.bounds.center();
        std::vector<Primitive> primitives;
        for (const engine::Primitive& primitive : mesh.primitives)
            if (!primitive.indices.empty())
                primitives.push_back(uploadPrimitive(primitive, relativeTo(primitive.positions, origin), primitive.normals,
                                                     primitive.tangents));
        meshes_.push_back(std::move(primitives));
        meshOrigins_.push_back(origin);
    }
    // Each (image, sampler, sRGB) once, in the order the materials first use it.
    using TextureKey = std::tuple<int, Sampler, bool>;
    std::vector<TextureKey> uploaded;
    for (const Material& material : scene.materials) {
        std::array<int, kMaterialTextureCount>& slots = materialTextures_.emplace_back();
        for (const MaterialTexture kind : kMaterialTextures) {
            const TextureRef& reference = materialTextureRef(material, kind);
            int& slot = slots[static_cast<unsigned>(kind)];
            slot = -1;
            if (reference.image < 0 || reference.image >= static_cast<int>(scene.images.size())) continue;
            const TextureKey key{reference.image, reference.sampler, isSrgb(kind)};
            auto found = std::find(uploaded.begin(), uploaded.end(), key);
            if (found == uploaded.end()) {
                textures_.push_back(uploadImage(scene.images[reference.image], reference.sampler, isSrgb(kind)));
                found = uploaded.insert(uploaded.end(), key);
            }
            slot = static_cast<int>(found - uploaded.begin());
        }
    }
    updateDeformed(scene);
}

void SceneGpu::updateDeformed(const Scene& scene) {
    std::unordered_map<int, DeformedInstance> kept;
    for (const MeshInstance& instance : scene.meshInstances) {
        if (!instance.deformed) continue;
        auto found = deformed_.find(instance.node);
        DeformedInstance gpu;
        if (found != deformed_.end() && found->second.mesh == instance.mesh) gpu = std::move(found->second);
        if (gpu.pose != instance.deformed) upload(gpu, scene.meshes.at(instance.mesh), *instance.deformed);
        gpu.mesh = instance.mesh;
        gpu.pose = instance.deformed;
        kept.emplace(instance.node, std::move(gpu));
    }
    deformed_ = std::move(kept);
}

void SceneGpu::upload(DeformedInstance& gpu, const Mesh& mesh, const DeformedMesh& pose) {
    const bool fresh = gpu.primitives.empty();
    std::size_t drawn = 0;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        if (mesh.primitives[p].indices.empty()) continue;  // as the meshes' list skips them
        const DeformedPrimitive& posed = pose.primitives.at(p);
        if (fresh) {
            gpu.primitives.push_back(uploadPrimitive(mesh.primitives[p], posed.positions, posed.normals,
                                                     posed.tangents, GL_DYNAMIC_STORAGE_BIT));
        } else {
            Primitive& primitive = gpu.primitives.at(drawn);
            updateArray(primitive.positions, posed.positions);
            updateArray(primitive.normals, posed.normals);
            if (primitive.hasTangents) updateArray(primitive.tangents, posed.tangents);
        }
        ++drawn;
    }
}

const std::vector<SceneGpu::Primitive>& SceneGpu::primitives(const MeshInstance& instance) const {
    if (instance.deformed) {
        const auto found = deformed_.find(instance.node);
        assert(found != deformed_.end() && found->second.pose == instance.deformed &&
               "SceneGpu::updateDeformed(scene) was not called after the scene changed");
        if (found != deformed_.end()) return found->second.primitives;
    }
    return meshes_.at(instance.mesh);
}

glm::dmat4 SceneGpu::modelMatrix(const MeshInstance& instance) const {
    if (instance.deformed) return glm::translate(instance.world, instance.deformed->origin);
    return glm::translate(instance.world, meshOrigins_.at(instance.mesh));
}

std::uint64_t SceneGpu::draw(const Primitive& primitive) const {
    return drawIndices(primitive, primitive.indices, 0, static_cast<std::uint32_t>(primitive.indexCount));
}

std::uint64_t SceneGpu::drawIndices(const Primitive& primitive, const gl::Buffer& indices, std::uint32_t first,
                                    std::uint32_t count) const {
    const GLuint vertexArray = primitive.vertexArray.id();
    const bool own = indices.id() == primitive.indices.id();
    // The element buffer is vertex-array state: swapped in for this draw, then put back.
    if (!own) glVertexArrayElementBuffer(vertexArray, indices.id());
    glBindVertexArray(vertexArray);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(count), GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(static_cast<std::uintptr_t>(first) * sizeof(std::uint32_t)));
    if (!own) glVertexArrayElementBuffer(vertexArray, primitive.indices.id());
    return count / 3;
}

unsigned SceneGpu::materialTexture(int material, MaterialTexture kind) const {
    if (material < 0 || material >= static_cast<int>(materialTextures_.size())) return 0;
    const int texture = materialTextures_[material][static_cast<unsigned>(kind)];
    return texture >= 0 ? textures_[texture].id() : 0;
}

} // namespace engine
