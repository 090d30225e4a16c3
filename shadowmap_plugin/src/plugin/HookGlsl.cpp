#include "plugin/HookGlsl.h"

#include "plugin/ShadowBlock.h"
#include "technique/Techniques.h"

#include <set>

namespace shadowmap {

namespace shaders {
extern const char shadow_data_glsl[];
extern const char map_shapes_glsl[];
extern const char visibility_glsl[];
extern const char texgen_glsl[];
extern const char disk_taps_glsl[];
extern const char moments_glsl[];
} // namespace shaders

namespace {

// The GLSL sampler types a lookup reads a 2D map, a cascaded (array) map and a cube map with:
// comparing samplers, or plain ones where the lookup compares depths itself.
struct SamplerTypes {
    const char* map2D;
    const char* array;
    const char* cube;
};

SamplerTypes samplerTypes(const std::string& glslName) {
    if (mapLookupNamed(glslName).comparesInHardware())
        return {"sampler2DShadow", "sampler2DArrayShadow", "samplerCubeShadow"};
    return {"sampler2D", "sampler2DArray", "samplerCube"};
}

void replaceAll(std::string& code, const std::string& placeholder, const std::string& value) {
    for (std::size_t at = code.find(placeholder); at != std::string::npos; at = code.find(placeholder, at))
        code.replace(at, placeholder.size(), value);
}

// visibility.glsl's functions for one lookup: $LOOKUP becomes its GLSL name, $SAMPLER2D,
// $SAMPLERARRAY and $SAMPLERCUBE its sampler types.
std::string mapShapeFunctions(const std::string& glslName) {
    std::string code = shaders::visibility_glsl;
    const SamplerTypes types = samplerTypes(glslName);
    replaceAll(code, "$SAMPLER2D", types.map2D);
    replaceAll(code, "$SAMPLERARRAY", types.array);
    replaceAll(code, "$SAMPLERCUBE", types.cube);
    replaceAll(code, "$LOOKUP", glslName);
    return code;
}

HookGlsl::Code generate(const std::vector<HookGlsl::Lookup>& lookups) {
    std::string lookupFunctions, declarations, dispatch, debugDispatch, texgenOutputs, texgen;
    std::set<std::string> written;
    for (const HookGlsl::Lookup& lookup : lookups)
        if (!lookup.screen && written.insert(lookup.glslName).second)
            lookupFunctions += std::string(mapLookupNamed(lookup.glslName).glsl()) + mapShapeFunctions(lookup.glslName);
    for (const HookGlsl::Lookup& lookup : lookups) {
        const std::string slot = std::to_string(lookup.slot);
        if (lookup.screen) {
            declarations += "layout(binding = " + std::to_string(lookup.unit) + ") uniform sampler2D uShadowVisibility" +
                            slot + ";\n";
            dispatch += "    if (lightSlot == " + slot + ") return texelFetch(uShadowVisibility" + slot +
                        ", ivec2(gl_FragCoord.xy), 0).r;\n";
            continue;
        }
        const SamplerTypes types = samplerTypes(lookup.glslName);
        const std::string suffix = "_" + lookup.glslName + "(";
        if (lookup.cascades > 0) {
            // Cascades pick their layer per pixel from the eye position: nothing interpolated.
            const std::string count = std::to_string(lookup.cascades);
            if (lookup.rawUnit >= 0) {
                declarations += "layout(binding = " + std::to_string(lookup.rawUnit) +
                                ") uniform sampler2DArray uShadowDepth" + slot + ";\n";
                debugDispatch += "    if (lightSlot == " + slot + ") return comparisonCascades(" + slot +
                                 ", eyePosition, eyeNormal, uShadowDepth" + slot + ", " + count + ");\n";
            }
            declarations += "layout(binding = " + std::to_string(lookup.unit) +
                            ") uniform " + types.array + " uShadowMap" + slot + ";\n";
            dispatch += "    if (lightSlot == " + slot + ") return shadowMapCascades" + suffix + slot +
                        ", eyePosition, eyeNormal, uShadowMap" + slot + ", " + count + ");\n";
            continue;
        }
        // The lookup's coordinates come interpolated from the vertex part (texgen.glsl).
        const std::string coordinate = (lookup.cube ? "vShadowToPoint" : "vShadowCoord") + slot;
        const std::string coordinateType = lookup.cube ? "vec3 " : "vec4 ";
        texgenOutputs += "out " + coordinateType + coordinate + ";\n";
        texgen += "    " + coordinate + (lookup.cube ? " = shadowToPoint(" : " = shadowCoord(") + slot +
                  ", eyePosition);\n";
        declarations += "in " + coordinateType + coordinate + ";\n";
        if (lookup.rawUnit >= 0) {
            declarations += "layout(binding = " + std::to_string(lookup.rawUnit) + ") uniform " +
                            (lookup.cube ? "samplerCube" : "sampler2D") + " uShadowDepth" + slot + ";\n";
            debugDispatch += "    if (lightSlot == " + slot + ") return " +
                             (lookup.cube ? "comparisonCube(" : "comparison2D(") + slot + ", " + coordinate +
                             ", eyePosition, eyeNormal, uShadowDepth" + slot + ");\n";
        }
        declarations += "layout(binding = " + std::to_string(lookup.unit) + ") uniform " +
                        (lookup.cube ? types.cube : types.map2D) + " uShadowMap" + slot + ";\n";
        dispatch += "    if (lightSlot == " + slot + ") return " + (lookup.cube ? "shadowMapCube" : "shadowMap2D") +
                    suffix + slot + ", " + coordinate + ", eyePosition, eyeNormal, uShadowMap" + slot + ");\n";
    }
    HookGlsl::Code code;
    code.fragment = shadowBlockGlslDefines() + shaders::shadow_data_glsl + shaders::moments_glsl + shaders::map_shapes_glsl +
                    shaders::disk_taps_glsl + lookupFunctions +
                    declarations +
                    "float lightVisibility(int lightSlot, vec3 eyePosition, vec3 eyeNormal) {\n" + dispatch +
                    "    return shadowData.params[lightSlot].w;\n}\n" +
                    "vec4 lightDebugColor(int lightSlot, vec3 eyePosition, vec3 eyeNormal) {\n" + debugDispatch +
                    "    return vec4(0.4, 0.4, 0.4, 1.0);\n}\n";
    code.vertex = shadowBlockGlslDefines() + shaders::shadow_data_glsl + shaders::texgen_glsl + texgenOutputs +
                  "void lightTexgen(vec3 eyePosition) {\n" + texgen + "}\n";
    return code;
}

} // namespace

const HookGlsl::Code& HookGlsl::codeFor(const std::vector<Lookup>& lookups) {
    if (auto found = codes_.find(lookups); found != codes_.end()) return found->second;
    Code code = generate(lookups);
    code.version = codes_.size() + 1;  // 0 is no version (Frame.h)
    return codes_.emplace(lookups, std::move(code)).first->second;
}

} // namespace shadowmap
