#include "plugin/VolumeRenderer.h"

#include "engine/render/SceneGpu.h"
#include "engine/scene/Deform.h"
#include "engine/scene/FrustumCull.h"
#include "engine/scene/ScreenFootprint.h"
#include "engine/scene/Scene.h"

#include <epoxy/gl.h>

#include <utility>


namespace shadowmap {

namespace shaders {
extern const char shadow_volume_vert[];
extern const char shadow_volume_frag[];
extern const char moments_vert[];
extern const char volume_resolve_frag[];
extern const char stencil_count_frag[];
} // namespace shaders

namespace {

// How far the volumes are pushed from the camera (glPolygonOffset units; no slope factor). The
// near caps are the casters' lit faces computed a second time (in double on the CPU, where the
// camera's depth pass rounds P_eye * V^-1 * M to float and multiplies in float), so a cap may
// round nearer than its own face, pass the depth test there and shadow the face. In reversed
// float depth a unit is about 2^-23 of the depth, so 256 units push a volume back by about
// 3e-5 of its distance. Measured, error % against truth (2CylinderEngine's spot key light at
// 480x270 / the showcase's spot at 320x180): 1 unit 3.59 / 13.2 (acne on every lit caster
// face), 16 units 0.208 / 0.015, 64 units 0.196 / 0.015, 256 units 0.187 / 0.019 (0.000 off
// edges in both), 1024 units 0.250 (volumes pushed through thin gaps leak). A slope factor of
// 1 moved every shadow edge on the box scenes by a pixel (0.3-0.6 % of their pixels wrong).
constexpr float kVolumeOffsetFactor = 0.0f;
constexpr float kVolumeOffsetUnits = 256.0f;

// The projection of the volumes' depth buffer. A perspective camera's becomes reversed Z with
// the far plane at infinity (window depth n / distance: near 1, infinity 0, glClipControl zero
// to one) in float depth, whose precision is relative, the same at every distance; the far caps
// at infinity land on depth 0 exactly. With the camera's own planes in 24-bit depth, surfaces a
// few units apart far from a near plane at 0.1 fell into one depth step and the offset above
// pushed volumes through them: 2CylinderEngine's fins lost their shadows on each other (9 % of
// the light's pixels leaked). An orthographic camera's depth is linear: kept.
struct VolumeDepth {
    glm::dmat4 projection;
    bool reversed = false;
};

VolumeDepth volumeDepth(const glm::dmat4& cameraProjection) {
    if (cameraProjection[3][3] != 0.0) return {cameraProjection, false};
    // A GL perspective (finite or infinite far): z_clip = P22 z + P32, and n = P32 / (P22 - 1).
    const double nearPlane = cameraProjection[3][2] / (cameraProjection[2][2] - 1.0);
    glm::dmat4 reversed = cameraProjection;
    reversed[2][2] = 0.0;
    reversed[3][2] = nearPlane;
    return {reversed, true};
}

void setDepthDirection(const VolumeDepth& depth) {
    glClipControl(GL_LOWER_LEFT, depth.reversed ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
    glDepthFunc(depth.reversed ? GL_GREATER : GL_LESS);
}

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

// The sphere, in eye space, around every receiver the camera sees: the volumes need to be
// right only there, so they end just past it instead of at infinity and their quads cover less
// of the screen. Radius 0 (nothing in view receives): extrusion to infinity.
ShadowVolumeBound receiverBound(const engine::Frame& frame, const glm::dmat4& viewMatrix) {
    const engine::FrameCamera& camera = frame.camera();
    const glm::dmat4 viewProjection = camera.projection * viewMatrix;
    engine::Aabb receivers;
    for (const engine::MeshInstance& instance : frame.scene().meshInstances)
        if (instance.receiveShadows && engine::boxIntersectsFrustum(viewProjection, instance.worldBounds))
            receivers.extend(instance.worldBounds);
    if (receivers.empty()) return {};
    const glm::dvec3 center = (receivers.min + receivers.max) * 0.5;
    return {glm::dvec3(viewMatrix * glm::dvec4(center, 1.0)), glm::length(receivers.max - receivers.min) * 0.5};
}

// The pixels where the light can light a receiver in view (engine/scene/ScreenFootprint.h).
engine::PixelRect lightFootprint(const engine::Frame& frame, const LightShadow& light) {
    const engine::Scene& scene = frame.scene();
    const engine::FrameCamera& camera = frame.camera();
    const glm::dmat4 viewProjection = camera.projection * glm::inverse(camera.eyeToWorld);
    std::vector<engine::Aabb> receivers;
    for (const engine::MeshInstance& instance : scene.meshInstances)
        if (instance.receiveShadows && engine::boxIntersectsFrustum(viewProjection, instance.worldBounds))
            receivers.push_back(instance.worldBounds);
    const engine::LightInstance& placed = scene.lightInstances[light.slot];
    return engine::lightFootprint(scene.lights[placed.light], placed, receivers, viewProjection, camera.width,
                                  camera.height);
}

} // namespace

VolumeRenderer::VolumeRenderer(bool onGpu, bool zPass)
    : volumeProgram_(compileProgram("shadow volumes", shaders::shadow_volume_vert, shaders::shadow_volume_frag)),
      resolveProgram_(compileProgram("shadow volume resolve", shaders::moments_vert, shaders::volume_resolve_frag)),
      framebuffer_(engine::gl::Framebuffer::create()),
      pointArray_(engine::gl::VertexArray::create()),
      empty_(engine::gl::VertexArray::create()),
      zPass_(zPass) {
    if (onGpu) gpu_ = std::make_unique<GpuVolumeExtrusion>();
}

void VolumeRenderer::prepareScene(const engine::Scene& scene) {
    meshes_.clear();
    for (const engine::Mesh& mesh : scene.meshes) {
        const CastingGeometry geometry = castingGeometry(scene, mesh, nullptr);
        meshes_.emplace_back(geometry.positions, geometry.indices);
    }
    if (gpu_) gpu_->prepareScene(meshes_);
    depthFrame_ = std::numeric_limits<std::uint64_t>::max();
}

void VolumeRenderer::ensureTargets(int width, int height) {
    if (depthStencil_.id() && depthStencil_.width() == width && depthStencil_.height() == height) return;
    depthStencil_ = engine::gl::Texture::create2D(GL_DEPTH32F_STENCIL8, width, height);
    // Sampled (writeStencilCounts) as its stencil counts, one texel a pixel.
    depthStencil_.setParameter(GL_DEPTH_STENCIL_TEXTURE_MODE, GL_STENCIL_INDEX);
    depthStencil_.setParameter(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    depthStencil_.setParameter(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    framebuffer_.attach(GL_DEPTH_STENCIL_ATTACHMENT, depthStencil_);
    depthFrame_ = std::numeric_limits<std::uint64_t>::max();
}

void VolumeRenderer::drawCameraDepth(const engine::Frame& frame, engine::PassContext& context, DepthRenderer& depth) {
    const VolumeDepth depthMapping = volumeDepth(frame.camera().projection);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_DEPTH_TEST);
    setDepthDirection(depthMapping);
    glDepthMask(GL_TRUE);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glClearDepth(depthMapping.reversed ? 0.0 : 1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    // Everything the lit pass draws that takes a shade, as it draws it (back faces of
    // single-sided materials culled, alpha-tested materials discarding).
    DepthPassStyle style;
    style.drawsNonCastingReceivers = true;
    style.cullsSingleSidedBackFaces = true;
    style.reversedZ = depthMapping.reversed;
    depth.draw(frame, context, depthMapping.projection * glm::inverse(frame.camera().eyeToWorld), style);
    glFrontFace(GL_CCW);
    depthFrame_ = frame.index();
}

VolumeCounts VolumeRenderer::buildVolumes(const engine::Frame& frame, const LightShadow& light) {
    const engine::Scene& scene = frame.scene();
    const engine::LightInstance& placed = scene.lightInstances[light.slot];
    const glm::dmat4 viewMatrix = glm::inverse(frame.camera().eyeToWorld);  // V^-1
    const ShadowVolumeBound bound = receiverBound(frame, viewMatrix);
    // z-pass for the closed casters whose volumes cannot hold the camera (CameraInVolume.h):
    // no caps to make or draw. A perspective camera only: with depth clamp an orthographic
    // one's rays reach behind it. Posed casters stay z-fail: their bounds are the rest pose's.
    const bool perspective = frame.camera().projection[3][3] == 0.0;
    const CameraRegion cameraNear = cameraRegion(frame.camera().eyeToWorld, frame.camera().projection);
    const glm::dvec4 lightWorld = lightInObject(placed, light.type, glm::dmat4(1.0));
    VolumeCounts counts;
    scratch_.clear();
    zPassScratch_.clear();
    gpuCasters_.clear();
    for (const engine::MeshInstance& instance : scene.meshInstances) {
        if (!instance.castShadows || instance.mesh < 0) continue;
        const ShadowVolumeMesh& volumeMesh = meshes_[instance.mesh];
        if (volumeMesh.triangleCount() == 0) continue;
        if (gpu_ && !instance.deformed && gpu_->extrudes(instance.mesh)) {
            gpuCasters_.push_back(&instance);
            ++counts.casters;
            ++counts.gpuCasters;
            continue;
        }
        const glm::dvec3 center = (instance.worldBounds.min + instance.worldBounds.max) * 0.5;
        const bool zPass = zPass_ && perspective && !instance.deformed && volumeMesh.closedOutward() &&
                           !volumeMayHoldCamera(lightWorld, cameraNear, center,
                                                glm::length(instance.worldBounds.max - instance.worldBounds.min) * 0.5);
        std::vector<glm::vec4>& out = zPass ? zPassScratch_ : scratch_;
        const VolumeCaps caps = zPass ? VolumeCaps::LeftOutIfClosed : VolumeCaps::Emitted;
        ShadowVolumeCounts added;
        const std::size_t first = out.size();
        if (instance.deformed) {
            // The pose moves the vertices, not the adjacency built at load. Posed vertices are
            // relative to the deformed mesh's origin, in the frame `world`.
            const glm::dmat4 model = glm::translate(instance.world, instance.deformed->origin);
            const CastingGeometry posed = castingGeometry(scene, scene.meshes[instance.mesh], instance.deformed.get());
            added = volumeMesh.appendVolume(lightInObject(placed, light.type, model), viewMatrix * model,
                                            posed.positions, out, bound, caps);
        } else {
            added = volumeMesh.appendVolume(lightInObject(placed, light.type, instance.world),
                                            viewMatrix * instance.world, out, bound, caps);
        }
        // A mirroring transform turns the volume inside out: its count would be -1 where the
        // others' are +1, and overlapping volumes of a mirrored and an unmirrored caster would
        // cancel into light. Rewound, every volume counts +1 inside.
        if (glm::determinant(glm::dmat3(instance.world)) < 0.0)
            for (std::size_t corner = first; corner + 2 < out.size(); corner += 3)
                std::swap(out[corner + 1], out[corner + 2]);
        ++counts.casters;
        counts.zPassCasters += zPass;
        counts.silhouetteEdges += added.silhouetteEdges;
        counts.capTriangles += added.capTriangles;
    }
    // One buffer: the z-fail volumes, then the z-pass ones from zPassFirst_.
    zPassFirst_ = scratch_.size();
    scratch_.insert(scratch_.end(), zPassScratch_.begin(), zPassScratch_.end());
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

void VolumeRenderer::writeStencilCounts(const engine::gl::Texture& target, const engine::PixelRect& footprint) {
    if (!countProgram_.id())
        countProgram_ = compileProgram("shadow volume counts", shaders::moments_vert, shaders::stencil_count_frag);
    if (!countFramebuffer_.id()) countFramebuffer_ = engine::gl::Framebuffer::create();
    // Its own framebuffer: the stencil it reads must not be attached where it draws.
    countFramebuffer_.attach(GL_COLOR_ATTACHMENT0, target);
    countFramebuffer_.bind();
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);  // outside the footprint no volume is counted
    if (footprint.empty()) return;
    glEnable(GL_SCISSOR_TEST);
    glScissor(footprint.x0, footprint.y0, footprint.x1 - footprint.x0, footprint.y1 - footprint.y0);
    glBindTextureUnit(0, depthStencil_.id());
    countProgram_.use();
    empty_.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindTextureUnit(0, 0);
    glDisable(GL_SCISSOR_TEST);
}

VolumeCounts VolumeRenderer::render(const engine::Frame& frame, engine::PassContext& context, DepthRenderer& depth,
                                    const LightShadow& light, const engine::gl::Texture* stencilCounts) {
    const engine::FrameCamera& camera = frame.camera();
    ensureTargets(camera.width, camera.height);
    framebuffer_.attach(GL_COLOR_ATTACHMENT0, light.visibility);
    framebuffer_.bind();
    glViewport(0, 0, camera.width, camera.height);
    if (depthFrame_ != frame.index()) drawCameraDepth(frame, context, depth);

    // Outside the light's footprint it lights nothing: no volume is counted there, and the
    // visibility is what a map gives outside its frustum (a spot's cone: 0; else 1).
    const engine::PixelRect footprint = lightFootprint(frame, light);
    const float outside = light.type == engine::Light::Type::Spot ? 0.0f : 1.0f;
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClearColor(outside, outside, outside, outside);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(footprint.x0, footprint.y0, footprint.x1 - footprint.x0, footprint.y1 - footprint.y0);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

    const VolumeCounts counts = footprint.empty() ? VolumeCounts{} : buildVolumes(frame, light);
    upload();
    if (counts.volumeTriangles > 0 || !gpuCasters_.empty()) {
        // A surface point inside k volumes ends with the count k (the volumes are wound outward,
        // ShadowVolumeMesh.h; the ops wrap, so the order of faces does not matter). z-fail: a
        // volume face behind the nearest surface counts, +1 facing away from the camera, -1
        // facing it; z-pass, for volumes that cannot hold the camera: a face in front counts,
        // +1 facing the camera, -1 facing away. Either way the counting side of the depth test
        // is made its passing side, so the samples passed (light.volumeFill) are those that count.
        const VolumeDepth depthMapping = volumeDepth(camera.projection);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glDepthMask(GL_FALSE);
        glEnable(GL_DEPTH_TEST);
        setDepthDirection(depthMapping);
        glDisable(GL_CULL_FACE);
        glFrontFace(GL_CCW);
        glEnable(GL_DEPTH_CLAMP);  // no far plane clips a volume's far end
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_ALWAYS, 0, 0xff);
        light.volumeFill.begin();
        // The near caps are the casters' own lit faces, made again on the CPU: pushed a little
        // away so that on those faces they lie behind the surface and count, as the rest of
        // their volume.
        glEnable(GL_POLYGON_OFFSET_FILL);
        const float away = depthMapping.reversed ? -1.0f : 1.0f;  // reversed Z: away is toward 0
        glPolygonOffset(away * kVolumeOffsetFactor, away * kVolumeOffsetUnits);
        volumeProgram_.use();
        volumeProgram_.set("uProjection", glm::mat4(depthMapping.projection));
        pointArray_.bind();
        if (zPassFirst_ < scratch_.size()) {
            glDepthFunc(depthMapping.reversed ? GL_GREATER : GL_LESS);
            glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
            glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
            glDrawArrays(GL_TRIANGLES, static_cast<GLint>(zPassFirst_), static_cast<GLsizei>(scratch_.size() - zPassFirst_));
            context.countDraw((scratch_.size() - zPassFirst_) / 3);
        }
        glDepthFunc(depthMapping.reversed ? GL_LEQUAL : GL_GEQUAL);
        glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
        glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
        if (zPassFirst_ > 0) {
            glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(zPassFirst_));
            context.countDraw(zPassFirst_ / 3);
        }
        const glm::dmat4 viewProjection = depthMapping.projection * glm::inverse(camera.eyeToWorld);
        const glm::dvec4 lightWorld = lightInObject(frame.scene().lightInstances[light.slot], light.type, glm::dmat4(1.0));
        for (const engine::MeshInstance* instance : gpuCasters_) {
            // A mirroring transform turns the volume inside out: its faces' window winding flips.
            glFrontFace(glm::determinant(glm::dmat3(instance->world)) < 0.0 ? GL_CW : GL_CCW);
            context.countDraw(gpu_->draw(*instance, viewProjection, lightWorld));
        }
        light.volumeFill.end();
        glFrontFace(GL_CCW);
        glBindVertexArray(0);
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
    glDisable(GL_SCISSOR_TEST);
    if (stencilCounts) writeStencilCounts(*stencilCounts, footprint);
    glDepthMask(GL_TRUE);
    glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    return counts;
}

} // namespace shadowmap
