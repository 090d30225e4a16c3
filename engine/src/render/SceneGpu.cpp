#include "engine/render/SceneGpu.h"

#include "engine/scene/Scene.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace engine {

namespace {

template <typename T>
gl::Buffer uploadArray(const std::vector<T>& data) {
    return gl::Buffer::create(data.size() * sizeof(T), data.data());
}

SceneGpu::Primitive uploadPrimitive(const engine::Primitive& source, const glm::dvec3& origin) {
    SceneGpu::Primitive gpu;
    std::vector<glm::vec3> relative(source.positions.size());
    for (std::size_t i = 0; i < relative.size(); ++i)
        relative[i] = glm::vec3(glm::dvec3(source.positions[i]) - origin);
    gpu.positions = uploadArray(relative);
    gpu.normals = uploadArray(source.normals);
    gpu.indices = uploadArray(source.indices);
    gpu.indexCount = static_cast<std::int32_t>(source.indices.size());
    gpu.material = source.material;
    gpu.vertexArray = gl::VertexArray::create();
    gpu.vertexArray.attribute(kAttribPosition, gpu.positions, 3, GL_FLOAT, sizeof(glm::vec3));
    gpu.vertexArray.attribute(kAttribNormal, gpu.normals, 3, GL_FLOAT, sizeof(glm::vec3));
    gpu.hasTexcoords = !source.texcoords.empty();
    if (gpu.hasTexcoords) {
        gpu.texcoords = uploadArray(source.texcoords);
        gpu.vertexArray.attribute(kAttribTexcoord, gpu.texcoords, 2, GL_FLOAT, sizeof(glm::vec2));
    }
    gpu.vertexArray.elementBuffer(gpu.indices);
    return gpu;
}

gl::Texture uploadImage(const Image& image) {
    const int levels =
        1 + static_cast<int>(std::floor(std::log2(std::max(image.width, image.height))));
    gl::Texture texture = gl::Texture::create2D(GL_SRGB8_ALPHA8, image.width, image.height, levels);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA,
                        GL_UNSIGNED_BYTE, image.rgba8.data());
    glGenerateTextureMipmap(texture.id());
    texture.setParameter(GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    texture.setParameter(GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    texture.setParameter(GL_TEXTURE_WRAP_S, GL_REPEAT);
    texture.setParameter(GL_TEXTURE_WRAP_T, GL_REPEAT);
    return texture;
}

} // namespace

SceneGpu::SceneGpu(const Scene& scene) {
    meshes_.reserve(scene.meshes.size());
    for (const Mesh& mesh : scene.meshes) {
        const glm::dvec3 origin = mesh.bounds.empty() ? glm::dvec3(0.0) : mesh.bounds.center();
        std::vector<Primitive> primitives;
        for (const engine::Primitive& primitive : mesh.primitives)
            if (!primitive.indices.empty()) primitives.push_back(uploadPrimitive(primitive, origin));
        meshes_.push_back(std::move(primitives));
        meshOrigins_.push_back(origin);
    }
    for (const Image& image : scene.images) images_.push_back(uploadImage(image));
    for (const Material& material : scene.materials) materialImage_.push_back(material.baseColorTexture.image);
}

glm::dmat4 SceneGpu::modelMatrix(const MeshInstance& instance) const {
    return glm::translate(instance.world, meshOrigins_.at(instance.mesh));
}

std::uint64_t SceneGpu::draw(const Primitive& primitive) const {
    glBindVertexArray(primitive.vertexArray.id());
    if (!primitive.hasTexcoords) glVertexAttrib2f(kAttribTexcoord, 0.0f, 0.0f);
    glDrawElements(GL_TRIANGLES, primitive.indexCount, GL_UNSIGNED_INT, nullptr);
    return static_cast<std::uint64_t>(primitive.indexCount / 3);
}

unsigned SceneGpu::baseColorTexture(int material) const {
    if (material < 0 || material >= static_cast<int>(materialImage_.size())) return 0;
    const int image = materialImage_[material];
    return image >= 0 && image < static_cast<int>(images_.size()) ? images_[image].id() : 0;
}

} // namespace engine
