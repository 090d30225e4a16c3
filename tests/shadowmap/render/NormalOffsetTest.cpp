// normal_offset against acne, for every light type and map shape: a floor alone, lit at a
// grazing angle, with the depth pass's polygon offset turned off. Without any bias the floor
// shadows itself in bands over much of its area (the control); the normal offset alone, moving
// each receiver a texel-scaled step off its surface before the lookup, must keep it lit.
#include "../../gl/GlTestContext.h"
#include "AnalyticShadows.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace {

constexpr int kWidth = 320, kHeight = 240;
constexpr double kFloorHalf = 8.0;
constexpr double kPi = 3.14159265358979323846;

struct GrazingLight {
    std::string name;
    engine::Light::Type type;
    glm::dvec3 position;
    nlohmann::json shadow;  // the map's shape
};

class NormalOffset : public engine::test::ShadowPluginTest {
protected:
    static void SetUpTestSuite() { loadPlugin(nlohmann::json::object()); }

    // The share of floor pixels (away from its rim) whose shade is below one half.
    static double darkenedFloor(const GrazingLight& light, double normalOffset) {
        engine::test::SceneBuilder builder;
        builder.addBox("floor", {-kFloorHalf, -0.5, -kFloorHalf}, {kFloorHalf, 0.0, kFloorHalf});
        nlohmann::json shadow = light.shadow;
        shadow["polygon_offset"] = {0.0, 0.0};
        shadow["normal_offset"] = normalOffset;
        shadow["resolution"] = 512;
        builder.addLight(light.name, light.type, light.position, glm::dvec3(0.0), shadow, 1.2);
        const engine::Scene scene = builder.build();
        const engine::FrameCamera view = engine::test::cameraLooking({0.0, 12.0, 9.0}, {0.0, 0.0, 0.0}, kWidth, kHeight);
        const std::vector<std::uint8_t> mask = engine::test::renderShadowMask(plugins(), scene, view, 0);
        int floor = 0, darkened = 0;
        // Away from the floor's rim.
        engine::test::forEachFloorPixel(view, 0.0, kFloorHalf - 0.5, [&](int x, int y, const glm::dvec3& p) {
            // A spot light's cone: only the floor inside it is lit at all.
            if (light.type == engine::Light::Type::Spot &&
                glm::dot(glm::normalize(p - light.position), glm::normalize(-light.position)) < std::cos(0.9))
                return;
            ++floor;
            darkened += mask[y * kWidth + x] < 128;
        });
        const double share = floor ? double(darkened) / floor : 1.0;
        std::printf("%s, normal_offset %.2f: %d of %d floor pixels darkened (%.3f%%)\n", light.name.c_str(),
                    normalOffset, darkened, floor, 100.0 * share);
        EXPECT_GT(floor, 10000) << light.name;
        return share;
    }
};

TEST_F(NormalOffset, KeepsAGrazinglyLitFloorLitWithoutAPolygonOffset) {
    const double elevation = 15.0 * kPi / 180.0;
    const glm::dvec3 low(std::cos(elevation), std::sin(elevation), 0.0);
    const std::vector<GrazingLight> lights = {
        {"sun", engine::Light::Type::Directional, low * 100.0, {{"cascades", 1}}},
        {"sun_cascades", engine::Light::Type::Directional, low * 100.0, {{"cascades", 3}}},
        {"spot", engine::Light::Type::Spot, glm::dvec3(9.0, 2.0, 0.0), nlohmann::json::object()},
        {"point", engine::Light::Type::Point, glm::dvec3(0.0, 1.0, 0.0), nlohmann::json::object()},
    };
    for (const GrazingLight& light : lights) {
        // The control: with no bias at all the floor shadows itself.
        EXPECT_GT(darkenedFloor(light, 0.0), 0.05) << light.name;
        // One texel along the normal keeps it lit (measured: 0 pixels for each light).
        EXPECT_LE(darkenedFloor(light, 1.0), 0.001) << light.name;
    }
}

} // namespace
