#include "engine/render/LitLights.h"

#include <epoxy/gl.h>

#include <cmath>

namespace engine {

namespace {

// std140 layout of lit.frag's LightData.
struct LightData {
    glm::vec4 positionRange;
    glm::vec4 direction;
    glm::vec4 radiance;
    glm::vec4 cone;
};

// lit.frag's LIGHT_DIRECTIONAL, LIGHT_SPOT and LIGHT_POINT.
int lightTypeCode(Light::Type type) {
    switch (type) {
    case Light::Type::Directional: return 0;
    case Light::Type::Spot: return 1;
    case Light::Type::Point: return 2;
    }
    return 2;
}

} // namespace

LitLights::LitLights()
    : buffer_(gl::Buffer::create(sizeof(LightData) * kMaxLights, nullptr, GL_DYNAMIC_STORAGE_BIT)) {}

void LitLights::upload(const Scene& scene, const FrameCamera& camera) {
    const glm::dmat4 view = glm::inverse(camera.eyeToWorld);
    LightData lights[kMaxLights]{};
    int count = 0;
    for (const LightInstance& placed : scene.lightInstances) {
        if (count == kMaxLights) break;
        const Light& light = scene.lights[placed.light];
        LightData& data = lights[count++];
        const glm::dvec3 eyePosition = glm::dvec3(view * glm::dvec4(placed.position(), 1.0));
        const glm::dvec3 eyeDirection = glm::normalize(glm::dmat3(view) * placed.direction());
        data.positionRange = glm::vec4(glm::vec3(eyePosition), static_cast<float>(light.range));
        data.direction = glm::vec4(glm::vec3(eyeDirection), 0.0f);
        data.radiance = glm::vec4(light.color * light.intensity, 0.0f);
        data.cone = glm::vec4(static_cast<float>(std::cos(light.outerConeAngle)),
                              static_cast<float>(std::cos(light.innerConeAngle)), 0.0f, 0.0f);
    }
    buffer_.update(0, sizeof(lights), lights);
}

std::string lightDefines(const Scene& scene, int lightCount, bool unrolled) {
    std::string defines = "#define LIGHT_COUNT " + std::to_string(lightCount) + "\n";
    if (lightCount == 0) return defines;
    std::string types;
    for (int slot = 0; slot < lightCount; ++slot) {
        const Light& light = scene.lights[scene.lightInstances[slot].light];
        const std::string type = std::to_string(lightTypeCode(light.type));
        types += (slot ? ", " : "") + type;
        if (unrolled) defines += (slot ? " F(" : "#define FOR_EACH_LIGHT(F) F(") + std::to_string(slot) + ", " + type + ")";
    }
    if (!unrolled)
        defines += "const int kLightTypes[LIGHT_COUNT] = int[](" + types + ");\n"
                   "#define FOR_EACH_LIGHT(F) for (int lightSlot = 0; lightSlot < LIGHT_COUNT; ++lightSlot) "
                   "{ F(lightSlot, kLightTypes[lightSlot]) }";
    defines += "\n";
    return defines;
}

} // namespace engine
