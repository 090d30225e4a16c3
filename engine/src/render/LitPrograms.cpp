#include "engine/render/LitPrograms.h"

#include "engine/render/SceneGpu.h"
#include "engine/scene/Scene.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace engine {

namespace shaders {
extern const char lit_vert[];
extern const char lit_frag[];
}

namespace {

// Without a plugin every light is fully visible and nothing is dimmed.
constexpr const char* kNoShadowsGlsl =
    "float lightVisibility(int lightSlot, vec3 eyePosition, vec3 eyeNormal) {\n"
    "    return 1.0;\n"
    "}\n"

    "vec4 lightDebugColor(int lightSlot, vec3 eyePosition, vec3 eyeNormal) {\n"
    "    return vec4(0.3, 0.3, 0.3, 1.0);\n"
    "}\n";

// A hook without a vertex part.
constexpr const char* kNoTexgenGlsl = "void lightTexgen(vec3 eyePosition) {}\n";

} // namespace

LitPrograms::ProgramKey LitPrograms::keyFor(const LightVisibilityHook* hook, const std::string& lightDefinesGlsl,
                                            LitOutput output, const std::string& loadShadesGlsl, unsigned variant) {
    // A hook without a version is known by its text (Frame.h).
    std::string hookIdentity;
    if (hook) hookIdentity = hook->glslVersion ? hook->owner : hook->owner + '\0' + hook->glsl + '\0' + hook->vertexGlsl;
    return {std::move(hookIdentity), hook ? hook->glslVersion : 0, lightDefinesGlsl, loadShadesGlsl, output, variant};
}

const gl::Program* LitPrograms::compiled(const LightVisibilityHook* hook, const std::string& lightDefinesGlsl,
                                         LitOutput output, const std::string& loadShadesGlsl, unsigned variant) const {
    const auto found = programs_.find(keyFor(hook, lightDefinesGlsl, output, loadShadesGlsl, variant));
    return found == programs_.end() ? nullptr : found->second.get();
}

const gl::Program& LitPrograms::programFor(const LightVisibilityHook* hook, const std::string& lightDefinesGlsl,
                                           LitOutput output, const std::string& loadShadesGlsl, unsigned variant) {
    ProgramKey key = keyFor(hook, lightDefinesGlsl, output, loadShadesGlsl, variant);
    auto found = programs_.find(key);
    if (found != programs_.end()) return *found->second;
    const std::string visibilityGlsl = hook ? hook->glsl : kNoShadowsGlsl;
    const std::string vertexTail = hook && !hook->vertexGlsl.empty() ? hook->vertexGlsl : kNoTexgenGlsl;
    const std::string header = "#version 450 core\n#define MAX_LIGHTS " + std::to_string(kMaxLights) +
                               "\n#define LIGHTS_BLOCK_BINDING " + std::to_string(kLightsUniformBinding) + "\n" +
                               lightDefinesGlsl +
                               (output == LitOutput::Comparison ? "#define LIGHT_DEBUG_VIEW\n" : "") +
                               (output == LitOutput::ShadowMask ? "#define LIGHT_MASK_VIEW\n" : "") +
                               (config_.exposure != 1.0f ? "#define EXPOSURE\n" : "") +
                               (config_.toneMapping == RendererConfig::ToneMapping::PbrNeutral
                                    ? "#define TONE_MAPPING_PBR_NEUTRAL\n"
                                    : "") +
                               materialDefines(variant, MaterialUse::Shading);
    const std::string fragmentTail = visibilityGlsl + "\n" + loadShadesGlsl;
    auto program = std::make_unique<gl::Program>(gl::Program::compile(
        "lit", {{GL_VERTEX_SHADER, header + materialVertexGlsl() + shaders::lit_vert + "\n" + vertexTail},
                {GL_FRAGMENT_SHADER, header + materialFragmentGlsl() + materialSurfaceGlsl() + shaders::lit_frag + "\n" +
                                         fragmentTail}}));
    return *programs_.emplace(std::move(key), std::move(program)).first->second;
}

std::vector<unsigned> variantsInUse(const Scene& scene, const SceneGpu& gpu) {
    std::vector<unsigned> variants;
    for (int mesh = 0; mesh < static_cast<int>(scene.meshes.size()); ++mesh)
        for (const SceneGpu::Primitive& primitive : gpu.meshPrimitives(mesh))
            if (const unsigned variant = materialFeatures(scene, gpu, primitive, MaterialUse::Shading);
                std::find(variants.begin(), variants.end(), variant) == variants.end())
                variants.push_back(variant);
    if (variants.empty()) variants.push_back(0);
    return variants;
}

} // namespace engine
