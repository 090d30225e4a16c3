#include "truth/SurfaceCapture.h"

#include "engine/gl/Framebuffer.h"
#include "engine/gl/Texture.h"
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
layout(location = ATTRIB_TEXCOORD) in vec2 inTexcoord;
uniform mat4 uModelView;   // V^-1 * M
uniform mat4 uProjection;  // P_eye
out vec3 gEyePosition;
out vec2 gTexcoord;
void main() {
    vec4 eyePosition = uModelView * vec4(inPosition, 1.0);
    gEyePosition = eyePosition.xyz;
    gTexcoord = inTexcoord;
    gl_Position = uProjection * eyePosition;
}
)";

// The face normal from the triangle itself, not the interpolated vertex normals: the shadow
// ray must leave from the side of the *geometry* the camera sees, and smooth normals point
// off the surface near silhouettes. Facing is decided once per triangle (a plane faces the
// eye everywhere or nowhere), against the projection's eye point: (0,0,0,1) for perspective,
// (0,0,1,0) (a direction) for orthographic.
constexpr const char* kGeometry = R"(
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
uniform vec4 uEyePoint;
in vec3 gEyePosition[];
in vec2 gTexcoord[];
out vec3 vEyePosition;
out vec2 vTexcoord;
flat out vec3 vFaceNormal;
void main() {
    vec3 n = cross(gEyePosition[1] - gEyePosition[0], gEyePosition[2] - gEyePosition[0]);
    vec3 toEye = uEyePoint.xyz - gEyePosition[0] * uEyePoint.w;
    if (dot(n, toEye) < 0.0) n = -n;
    for (int i = 0; i < 3; ++i) {
        gl_Position = gl_in[i].gl_Position;
        vEyePosition = gEyePosition[i];
        vTexcoord = gTexcoord[i];
        vFaceNormal = n;
        EmitVertex();
    }
    EndPrimitive();
}
)";

// Same alpha-mask discard as engine/shaders/lit.frag, so coverage matches the shaded image.
constexpr const char* kFragment = R"(
uniform vec4 uBaseColorFactor;
uniform bool uHasBaseColorTexture;
uniform float uAlphaCutoff;  // < 0: no alpha test
layout(binding = 0) uniform sampler2D uBaseColorTexture;
uniform int uInstance;
in vec3 vEyePosition;
in vec2 vTexcoord;
flat in vec3 vFaceNormal;
layout(location = 0) out vec4 outPosition;  // xyz eye position, w = 1 (covered)
layout(location = 1) out vec4 outNormal;    // xyz eye face normal, w = mesh instance
void main() {
    float alpha = uBaseColorFactor.a;
    if (uHasBaseColorTexture) alpha *= texture(uBaseColorTexture, vTexcoord).a;
    if (uAlphaCutoff >= 0.0 && alpha < uAlphaCutoff) discard;
    float len = length(vFaceNormal);
    outPosition = vec4(vEyePosition, 1.0);
    outNormal = vec4(len > 0.0 ? vFaceNormal / len : vec3(0.0, 0.0, 1.0), float(uInstance));
}
)";

std::string header() {
    return "#version 450 core\n#define ATTRIB_POSITION " + std::to_string(engine::kAttribPosition) +
           "\n#define ATTRIB_TEXCOORD " + std::to_string(engine::kAttribTexcoord) + "\n";
}

} // namespace

SurfaceCapture::SurfaceCapture()
    : program_(engine::gl::Program::compile("truth_surface_capture",
                                            {{GL_VERTEX_SHADER, header() + kVertex},
                                             {GL_GEOMETRY_SHADER, header() + kGeometry},
                                             {GL_FRAGMENT_SHADER, header() + kFragment}})) {}

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

    program_.use();
    program_.set("uProjection", glm::mat4(camera.projection));
    // A perspective projection has (0,0,-1,0) as its last row; an orthographic one (0,0,0,1).
    const bool perspective = camera.projection[3][3] == 0.0;
    program_.set("uEyePoint", perspective ? glm::vec4(0, 0, 0, 1) : glm::vec4(0, 0, 1, 0));

    const glm::dmat4 view = glm::inverse(camera.eyeToWorld);
    static const Material kDefaultMaterial{};
    for (std::size_t i = 0; i < scene.meshInstances.size(); ++i) {
        const MeshInstance& instance = scene.meshInstances[i];
        program_.set("uModelView", glm::mat4(view * gpu.modelMatrix(instance)));  // double, then cast
        program_.set("uInstance", static_cast<int>(i));
        glFrontFace(glm::determinant(glm::dmat3(instance.world)) < 0.0 ? GL_CW : GL_CCW);
        for (const SceneGpu::Primitive& primitive : gpu.primitives(instance.mesh)) {
            const Material& material =
                primitive.material >= 0 ? scene.materials[primitive.material] : kDefaultMaterial;
            program_.set("uBaseColorFactor", material.baseColorFactor);
            program_.set("uAlphaCutoff",
                         material.alphaMode == AlphaMode::Mask ? material.alphaCutoff : -1.0f);
            const unsigned texture = gpu.baseColorTexture(primitive.material);
            program_.set("uHasBaseColorTexture", texture != 0 ? 1 : 0);
            glBindTextureUnit(0, texture);
            if (material.doubleSided) glDisable(GL_CULL_FACE);
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
    const std::size_t count = out.pixelCount();
    out.worldPosition.assign(count, glm::dvec3(0.0));
    out.worldNormal.assign(count, glm::dvec3(0.0));
    out.covered.assign(count, 0);
    out.instance.assign(count, -1);
    const glm::dmat3 normalToWorld = glm::transpose(glm::inverse(glm::dmat3(camera.eyeToWorld)));
    for (std::size_t i = 0; i < count; ++i) {
        const float* p = &eyePositions[4 * i];
        const float* n = &eyeNormals[4 * i];
        if (p[3] < 0.5f) continue;
        out.covered[i] = 1;
        out.instance[i] = static_cast<std::int32_t>(n[3]);
        out.worldPosition[i] = glm::dvec3(camera.eyeToWorld * glm::dvec4(p[0], p[1], p[2], 1.0));
        out.worldNormal[i] = glm::normalize(normalToWorld * glm::dvec3(n[0], n[1], n[2]));
    }
    return out;
}

} // namespace truth
