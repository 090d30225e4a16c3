#include "engine/render/LitLights.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>

namespace engine {

namespace {

// lit.frag's LightData, std140 (and std430, the same for four vec4s).
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

LightData eyeSpaceLight(const Scene& scene, const LightInstance& placed, const glm::dmat4& view) {
    const Light& light = scene.lights[placed.light];
    LightData data;
    const glm::dvec3 eyePosition = glm::dvec3(view * glm::dvec4(placed.position(), 1.0));
    const glm::dvec3 eyeDirection = glm::normalize(glm::dmat3(view) * placed.direction());
    data.positionRange = glm::vec4(glm::vec3(eyePosition), static_cast<float>(light.range));
    data.direction = glm::vec4(glm::vec3(eyeDirection), 0.0f);
    data.radiance = glm::vec4(light.color * light.intensity, 0.0f);
    data.cone = glm::vec4(static_cast<float>(std::cos(light.outerConeAngle)),
                          static_cast<float>(std::cos(light.innerConeAngle)), 0.0f, 0.0f);
    return data;
}

// Uploads `bytes` into `buffer`, first replacing it by one of the next power of two of bytes
// when it is smaller (a buffer's storage is immutable). An empty upload keeps a 16-byte
// buffer, so every binding has storage.
void uploadGrowing(gl::Buffer& buffer, const void* data, std::size_t bytes) {
    if (buffer.size() < std::max<std::size_t>(bytes, 16)) {
        std::size_t size = 16;
        while (size < bytes) size *= 2;
        buffer = gl::Buffer::create(size, nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    if (bytes) buffer.update(0, bytes, data);
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
        lights[count++] = eyeSpaceLight(scene, placed, view);
    }
    buffer_.update(0, sizeof(lights), lights);
}

void ClusteredLights::upload(const Scene& scene, const FrameCamera& camera, const std::vector<float>& dimming,
                             const LightTiles& tiles) {
    const glm::dmat4 view = glm::inverse(camera.eyeToWorld);
    std::vector<LightData> lights;
    lights.reserve(scene.lightInstances.size());
    for (std::size_t slot = 0; slot < scene.lightInstances.size(); ++slot) {
        const LightInstance& placed = scene.lightInstances[slot];
        LightData data = eyeSpaceLight(scene, placed, view);
        data.direction.w = static_cast<float>(lightTypeCode(scene.lights[placed.light].type));
        data.cone.z = slot < dimming.size() ? dimming[slot] : 0.0f;
        lights.push_back(data);
    }
    uploadGrowing(lights_, lights.data(), lights.size() * sizeof(LightData));
    uploadGrowing(ranges_, tiles.ranges.data(), tiles.ranges.size() * sizeof(std::uint32_t));
    uploadGrowing(lists_, tiles.lights.data(), tiles.lights.size() * sizeof(std::uint32_t));
}

void ClusteredLights::bind() const {
    lights_.bindBase(GL_SHADER_STORAGE_BUFFER, kClusteredLightsBinding);
    ranges_.bindBase(GL_SHADER_STORAGE_BUFFER, kLightTileRangesBinding);
    lists_.bindBase(GL_SHADER_STORAGE_BUFFER, kTileLightsBinding);
}

std::string clusteredLightDefines() {
    return "#define LIGHT_COUNT 0\n#define CLUSTERED_LIGHTS\n#define CLUSTERED_LIGHTS_BINDING " +
           std::to_string(kClusteredLightsBinding) + "\n#define LIGHT_TILE_RANGES_BINDING " +
           std::to_string(kLightTileRangesBinding) + "\n#define TILE_LIGHTS_BINDING " +
           std::to_string(kTileLightsBinding) + "\n#define LIGHT_TILE_SIZE " + std::to_string(kLightTileSize) + "\n";
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
