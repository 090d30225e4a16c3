#include "truth/SurfaceCapture.h"

#include "engine/gl/Framebuffer.h"
#include "engine/gl/Texture.h"
#include "engine/render/MaterialShading.h"
#include "engine/render/SceneGpu.h"
#include "engine/render/TextureReadback.h"
#include "engine/scene/Scene.h"

#include <string>

namespace truth {

namespace {

// Eye space throughout, like engine/shaders/lit.vert: the CPU hands over V^-1 * M composed
// in double, so the floats here are camera-relative and small.
constexpr const char* kVertex = R"(
layout(location = ATTRIB_POSITION) in vec3 inPosition;
uniform mat4 uModelView;   // V^-1 * M
uniform mat4 uProjection;  // P_eye
out vec3 gEyePosition;
void main() {
    vec4 eyePosition = uModelView * vec4(inPosition, 1.0);
    gEyePosition = eyePosition.xyz;
    gl_Position = uProjection * eyePosition;
    passMaterialInputs();
}
)";

// The face normal from the triangle itself, not the interpolated vertex normals: the shadow
// ray must leave from the side of the *geometry* the camera sees, and smooth normals point
// off the surface near silhouettes. Facing is decided once per triangle (a plane faces the
// eye everywhere or nowhere), against the projection's eye point: (0,0,0,1) for perspective,
// (0,0,1,0) (a direction) for orthographic. The material varyings pass through.
constexpr const char* kGeometry = R"(
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
uniform vec4 uEyePoint;
in vec3 gEyePosition[];
out vec3 vEyePosition;
flat out vec3 vFaceNormal;
#ifdef MATERIAL_VARYINGS
in MATERIAL_VARYINGS materialIn[];
out MATERIAL_VARYINGS materialOut;
#endif
void main() {
    vec3 n = cross(gEyePosition[1] - gEyePosition[0], gEyePosition[2] - gEyePosition[0]);
    vec3 toEye = uEyePoint.xyz - gEyePosition[0] * uEyePoint.w;
    if (dot(n, toEye) < 0.0) n = -n;
    for (int i = 0; i < 3; ++i) {
        gl_Position = gl_in[i].gl_Position;
        vEyePosition = gEyePosition[i];
        vFaceNormal = n;
#ifdef BASE_COLOR_TEXTURE
        materialOut.baseColorUv = materialIn[i].baseColorUv;
#endif
#ifdef VERTEX_COLOR
        materialOut.color = materialIn[i].color;
#endif
        EmitVertex();
    }
    EndPrimitive();
}
)";

// The lit pass's own material code (MaterialShading.h): the same alpha test, so coverage
// matches the shaded image.
constexpr const char* kFragment = R"(
uniform int uInstance;
uniform bool uReceivesShadows;
in vec3 vEyePosition;
flat in vec3 vFaceNormal;
layout(location = 0) out vec4 outPosition;  // xyz eye position, w = 1 covered, 2 covered and receiving
layout(location = 1) out vec4 outNormal;    // xyz eye face normal, w = mesh instance
void main() {
#ifdef ALPHA_TEST
    discardBelowAlphaCutoff(materialBaseColor().a);
#endif
    float len = length(vFaceNormal);
    outPosition = vec4(vEyePosition, uReceivesShadows ? 2.0 : 1.0);
    outNormal = vec4(len > 0.0 ? vFaceNormal / len : vec3(0.0, 0.0, 1.0), float(uInstance));
}
)";

engine::gl::Program compileCaptureProgram(unsigned materialFeatures) {
    const std::string header = "#version 450 core\n#define ATTRIB_POSITION " +
                               std::to_string(engine::kAttribPosition) + "\n" +
                               engine::materialDefines(materialFeatures, engine::MaterialUse::ViewCoverage);
    return engine::gl::Program::compile(
        "truth_surface_capture", {{GL_VERTEX_SHADER, header + engine::materialVertexGlsl() + kVertex},
                                  {GL_GEOMETRY_SHADER, header + kGeometry},
                                  {GL_FRAGMENT_SHADER, header + engine::materialFragmentGlsl() + kFragment}});
}

} // namespace

SurfaceCapture::SurfaceCapture() { program(0); }

const engine::gl::Program& SurfaceCapture::program(unsigned materialFeatures) const {
    auto found = programs_.find(materialFeatures);
    if (found == programs_.end())
        found = programs_.emplace(materialFeatures, compileCaptureProgram(materialFeatures)).first;
    return found->second;
}

SurfaceBuffer SurfaceCapture::capture(const engine::Scene& scene, const engine::SceneGpu& gpu,
                                      const engine::FrameCamera& camera) const {
    using namespace engine;
    const int width = camera.width, height = camera.height;
    gl::Texture positions = gl::Texture::create2D(GL_RGBA32F, width, height);
    gl::Texture normals = gl::Texture::create2D(GL_RGBA32F, width, height);
    gl::Texture depth = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, width, height);
    gl::Framebuffer framebuffer = gl::Framebuffer::create();
    framebuffer.attach(GL_COLOR_ATTACHMENT0, positions);
    framebuffer.attach(GL_COLOR_ATTACHMENT1, normals);
    framebuffer.attach(GL_DEPTH_ATTACHMENT, depth);
    framebuffer.setDrawBuffers({GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1});
    framebuffer.requireComplete("truth surface capture");
    framebuffer.bind();
    glViewport(0, 0, width, height);
    const glm::vec4 clearPosition(0.0f), clearNormal(0.0f, 0.0f, 0.0f, -1.0f);
    const float farDepth = 1.0f;
    glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, &clearPosition[0]);
    glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 1, &clearNormal[0]);
    glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &farDepth);
    // The lit pass's depth state, so both keep the same surface where depths tie.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);

    // A perspective projection has (0,0,-1,0) as its last row; an orthographic one (0,0,0,1).
    const bool perspective = camera.projection[3][3] == 0.0;
    const glm::vec4 eyePoint = perspective ? glm::vec4(0, 0, 0, 1) : glm::vec4(0, 0, 1, 0);

    const glm::dmat4 view = glm::inverse(camera.eyeToWorld);
    for (std::size_t i = 0; i < scene.meshInstances.size(); ++i) {
        const MeshInstance& instance = scene.meshInstances[i];
        const glm::mat4 modelView(view * gpu.modelMatrix(instance));  // double, then cast
        glFrontFace(glm::determinant(glm::dmat3(instance.world)) < 0.0 ? GL_CW : GL_CCW);
        for (const SceneGpu::Primitive& primitive : gpu.primitives(instance)) {
            const unsigned features = materialFeatures(scene, gpu, primitive, MaterialUse::ViewCoverage);
            const gl::Program& drawing = program(features);
            drawing.use();
            drawing.set("uProjection", glm::mat4(camera.projection));
            drawing.set("uEyePoint", eyePoint);
            drawing.set("uModelView", modelView);
            drawing.set("uInstance", static_cast<int>(i));
            drawing.set("uReceivesShadows", instance.receiveShadows && primitive.receiveShadows ? 1 : 0);
            applyMaterial(drawing, scene, gpu, primitive, features, MaterialUse::ViewCoverage);
            if (materialOf(scene, primitive).doubleSided) glDisable(GL_CULL_FACE);
            else glEnable(GL_CULL_FACE);
            gpu.draw(primitive);
        }
    }
    glFrontFace(GL_CCW);
    glEnable(GL_CULL_FACE);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    const std::vector<float> eyePositions = readTextureFloatTopDown(positions, 4);
    const std::vector<float> eyeNormals = readTextureFloatTopDown(normals, 4);

    // World = V * eye in double: only the camera-relative offset was ever a float.
    SurfaceBuffer out;
    out.width = width;
    out.height = height;
    out.cameraPosition = camera.position();
    out.camera = camera;
    const std::size_t count = out.pixelCount();
    out.worldPosition.assign(count, glm::dvec3(0.0));
    out.worldNormal.assign(count, glm::dvec3(0.0));
    out.covered.assign(count, 0);
    out.instance.assign(count, -1);
    out.receivesShadows.assign(count, 0);
    const glm::dmat3 normalToWorld = glm::transpose(glm::inverse(glm::dmat3(camera.eyeToWorld)));
    for (std::size_t i = 0; i < count; ++i) {
        const float* p = &eyePositions[4 * i];
        const float* n = &eyeNormals[4 * i];
        if (p[3] < 0.5f) continue;
        out.covered[i] = 1;
        out.receivesShadows[i] = p[3] > 1.5f ? 1 : 0;
        out.instance[i] = static_cast<std::int32_t>(n[3]);
        out.worldPosition[i] = glm::dvec3(camera.eyeToWorld * glm::dvec4(p[0], p[1], p[2], 1.0));
        out.worldNormal[i] = glm::normalize(normalToWorld * glm::dvec3(n[0], n[1], n[2]));
    }
    return out;
}

} // namespace truth
