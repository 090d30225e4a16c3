#include "plugin/VolumeRenderer.h"

#include "engine/render/SceneGpu.h"
#include "engine/scene/Deform.h"
#include "engine/scene/Scene.h"

#include <epoxy/gl.h>


namespace shadowmap {

namespace shaders {
extern const char shadow_volume_vert[];
extern const char shadow_volume_frag[];
extern const char moments_vert[];
extern const char volume_resolve_frag[];
} // namespace shaders

namespace {

// How far the volumes are pushed from the camera (glPolygonOffset). The near caps are the
// casters' lit faces computed a second time (in double on the CPU, where the camera's depth
// pass composes P_eye * V^-1 * M in float), so the two differ by a few float roundings of
// window depth: a few 2^-24 units, and at most a fraction of the face's depth slope per pixel
// for the lateral rounding. Without the push a cap that rounds nearer than its own face passes
// the depth test there and the face shadows itself.
constexpr float kVolumeOffsetFactor = 0.0f;
constexpr float kVolumeOffsetUnits = 4.0f;

engine::gl::Program compileProgram(const std::string& name, const char* vertex, const char* fragment) {
    const std::string header = "#version 450 core\n";
    return engine::gl::Program::compile(name,
                                        {{GL_VERTEX_SHADER, header + vertex}, {GL_FRAGMENT_SHADER, header + fragment}});
}

// The positions and triangles of a mesh's primitives that cast, as one list, so that edges
// shared across primitives (a material boundary) join; `posed` (a deformed instance) replaces
// the positions primitive by primitive.
struct CastingGeometry {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
};

bool castsVolume(const engine::Scene& scene, const engine::Primitive& primitive) {
    if (!primitive.castShadows) return false;
    return primitive.material < 0 || !engine::castsAlphaTested(scene.materials[primitive.material]);
}

CastingGeometry castingGeometry(const engine::Scene& scene, const engine::Mesh& mesh,
                                const engine::DeformedMesh* posed) {
    CastingGeometry geometry;
    for (std::size_t index = 0; index < mesh.primitives.size(); ++index) {
        const engine::Primitive& primitive = mesh.primitives[index];
        if (!castsVolume(scene, primitive)) continue;
        const auto first = static_cast<std::uint32_t>(geometry.positions.size());
        const std::vector<glm::vec3>& positions = posed ? posed->primitives[index].positions : primitive.positions;
        geometry.positions.insert(geometry.positions.end(), positions.begin(), positions.end());
        for (std::uint32_t vertex : primitive.indices) geometry.indices.push_back(first + vertex);
    }
    return geometry;
}

// The light in the frame the mesh's positions are given in: a point (w = 1) for spot and point
// lights, the direction toward the light (w = 0) for a directional one.
glm::dvec4 lightInObject(const engine::LightInstance& light, engine::Light::Type type, const glm::dmat4& model) {
    const glm::dvec4 world = type == engine::Light::Type::Directional ? glm::dvec4(-light.direction(), 0.0)
                                                                       : glm::dvec4(light.position(), 1.0);
    return glm::inverse(model) * world;
}

} // namespace

VolumeRenderer::VolumeRenderer()
    : volumeProgram_(compileProgram("shadow volumes", shaders::shadow_volume_vert, shaders::shadow_volume_frag)),
      resolveProgram_(compileProgram("shadow volume resolve", shaders::moments_vert, shaders::volume_resolve_frag)),
      framebuffer_(engine::gl::Framebuffer::create()),
      pointArray_(engine::gl::VertexArray::create()),
      empty_(engine::gl::VertexArray::create()) {}

void VolumeRenderer::prepareScene(const engine::Scene& scene) {
    meshes_.clear();
    for (const engine::Mesh& mesh : scene.meshes) {
        const CastingGeometry geometry = castingGeometry(scene, mesh, nullptr);
        meshes_.emplace_back(geometry.positions, geometry.indices);
    }
    depthFrame_ = std::numeric_limits<std::uint64_t>::max();
}

void VolumeRenderer::ensureTargets(int width, int height) {
    if (depthStencil_.id() && depthStencil_.width() == width && depthStencil_.height() == height) return;
    depthStencil_ = engine::gl::Texture::create2D(GL_DEPTH24_STENCIL8, width, height);
    framebuffer_.attach(GL_DEPTH_STENCIL_ATTACHMENT, depthStencil_);
    depthFrame_ = std::numeric_limits<std::uint64_t>::max();
}

void VolumeRenderer::drawCameraDepth(const engine::Frame& frame, engine::PassContext& context, DepthRenderer& depth) {
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    // Everything the lit pass draws that takes a shade, as it draws it (back faces of
    // single-sided materials culled, alpha-tested materials discarding).
    DepthPassStyle style;
    style.drawsNonCastingReceivers = true;
    style.cullsSingleSidedBackFaces = true;
    const engine::FrameCamera& camera = frame.camera();
    depth.draw(frame, context, camera.projection * glm::inverse(camera.eyeToWorld), style);
    glFrontFace(GL_CCW);
    depthFrame_ = frame.index();
}

VolumeCounts VolumeRenderer::buildVolumes(const engine::Frame& frame, const LightShadow& light) {
    const engine::Scene& scene = frame.scene();
    const engine::LightInstance& placed = scene.lightInstances[light.slot];
    const glm::dmat4 viewMatrix = glm::inverse(frame.camera().eyeToWorld);  // V^-1
    VolumeCounts counts;
    scratch_.clear();
    for (const engine::MeshInstance& instance : scene.meshInstances) {
        if (!instance.castShadows || instance.mesh < 0) continue;
        const ShadowVolumeMesh& volumeMesh = meshes_[instance.mesh];
        if (volumeMesh.triangleCount() == 0) continue;
        ShadowVolumeCounts added;
        if (instance.deformed) {
            // The pose moves the vertices, not the adjacency built at load. Posed vertices are
            // relative to the deformed mesh's origin, in the frame `world`.
            const glm::dmat4 model = glm::translate(instance.world, instance.deformed->origin);
            const CastingGeometry posed = castingGeometry(scene, scene.meshes[instance.mesh], instance.deformed.get());
            added = volumeMesh.appendVolume(lightInObject(placed, light.type, model), viewMatrix * model,
                                            posed.positions, scratch_);
        } else {
            added = volumeMesh.appendVolume(lightInObject(placed, light.type, instance.world),
                                            viewMatrix * instance.world, scratch_);
        }
        ++counts.casters;
        counts.silhouetteEdges += added.silhouetteEdges;
        counts.capTriangles += added.capTriangles;
    }
    counts.volumeTriangles = scratch_.size() / 3;
    return counts;
}

void VolumeRenderer::upload() {
    if (scratch_.empty()) return;
    if (scratch_.size() > pointCapacity_) {
        // Grown to twice the need, so a volume that grows a little each frame reallocates rarely.
        pointCapacity_ = scratch_.size() * 2;
        points_ = engine::gl::Buffer::create(pointCapacity_ * sizeof(glm::vec4), nullptr, GL_DYNAMIC_STORAGE_BIT);
        pointArray_.attribute(0, points_, 4, GL_FLOAT, sizeof(glm::vec4), 0);
    }
    points_.update(0, scratch_.size() * sizeof(glm::vec4), scratch_.data());
}

VolumeCounts VolumeRenderer::render(const engine::Frame& frame, engine::PassContext& context, DepthRenderer& depth,
                                    const LightShadow& light) {
    const engine::FrameCamera& camera = frame.camera();
    ensureTargets(camera.width, camera.height);
    framebuffer_.attach(GL_COLOR_ATTACHMENT0, light.visibility);
    framebuffer_.bind();
    glViewport(0, 0, camera.width, camera.height);
    if (depthFrame_ != frame.index()) drawCameraDepth(frame, context, depth);

    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

    const VolumeCounts counts = buildVolumes(frame, light);
    upload();
    if (counts.volumeTriangles > 0) {
        // z-fail: a volume face behind the nearest surface counts, +1 facing away from the
        // camera, -1 facing it (wrapping, so the order of faces does not matter); a surface
        // point inside k volumes ends with k. The volumes are wound outward (ShadowVolumeMesh.h).
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glDepthMask(GL_FALSE);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDisable(GL_CULL_FACE);
        glFrontFace(GL_CCW);
        glEnable(GL_DEPTH_CLAMP);  // the far caps at infinity stay, at depth 1
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_ALWAYS, 0, 0xff);
        glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
        glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
        // The near caps are the casters' own lit faces, made again on the CPU: pushed a little
        // away so that on those faces they fail the depth test, as the rest of their volume.
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(kVolumeOffsetFactor, kVolumeOffsetUnits);
        volumeProgram_.use();
        volumeProgram_.set("uProjection", glm::mat4(camera.projection));
        pointArray_.bind();
        glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(scratch_.size()));
        context.countDraw(counts.volumeTriangles);
        glDisable(GL_POLYGON_OFFSET_FILL);
        glDisable(GL_DEPTH_CLAMP);
    }
    // Resolve: 1 where no volume holds the nearest surface.
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 0, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    resolveProgram_.use();
    empty_.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDisable(GL_STENCIL_TEST);
    glDepthMask(GL_TRUE);
    return counts;
}

} // namespace shadowmap
