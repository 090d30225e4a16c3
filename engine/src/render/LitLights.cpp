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

// Makes `texture` a width x height (at least) texture of `format`, keeping it when it is
// large enough, and uploads `rows` rows of `data` (width texels each) into its bottom.
void uploadGrowing(gl::Texture& texture, GLenum internalFormat, GLenum format, GLenum type, int width, int height,
                   const void* data, int rows) {
    if (!texture.id() || texture.width() < width || texture.height() < height) {
        int grownHeight = 1;
        while (grownHeight < height) grownHeight *= 2;
        texture = gl::Texture::create2D(internalFormat, std::max(width, 1), grownHeight);
        texture.setParameter(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        texture.setParameter(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    if (rows > 0 && width > 0) glTextureSubImage2D(texture.id(), 0, 0, 0, width, rows, format, type, data);
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
    const int lightCount = static_cast<int>(lights.size());
    uploadGrowing(lights_, GL_RGBA32F, GL_RGBA, GL_FLOAT, 4, std::max(lightCount, 1), lights.data(), lightCount);
    uploadGrowing(ranges_, GL_RG32UI, GL_RG_INTEGER, GL_UNSIGNED_INT, tiles.columns, tiles.rows, tiles.ranges.data(),
                  tiles.rows);
    // The lists fill whole rows: the last one is padded.
    std::vector<std::uint32_t> lists = tiles.lights;
    const int rows = static_cast<int>((lists.size() + kTileListsWidth - 1) / kTileListsWidth);
    lists.resize(static_cast<std::size_t>(rows) * kTileListsWidth, 0);
    uploadGrowing(lists_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, kTileListsWidth, std::max(rows, 1), lists.data(),
                  rows);
}

void ClusteredLights::bind() const {
    lights_.bind(kLightDataUnit);
    ranges_.bind(kTileRangesUnit);
    lists_.bind(kTileLightsUnit);
    for (const int unit : {kLightDataUnit, kTileRangesUnit, kTileLightsUnit}) glBindSampler(unit, 0);
}

std::string clusteredLightDefines() {
    return "#define LIGHT_COUNT 0\n#define CLUSTERED_LIGHTS\n#define LIGHT_DATA_UNIT " + std::to_string(kLightDataUnit) +
           "\n#define TILE_RANGES_UNIT " + std::to_string(kTileRangesUnit) + "\n#define TILE_LIGHTS_UNIT " +
           std::to_string(kTileLightsUnit) + "\n#define LIGHT_TILE_SIZE " + std::to_string(kLightTileSize) +
           "\n#define TILE_LISTS_WIDTH " + std::to_string(kTileListsWidth) + "\n";
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
