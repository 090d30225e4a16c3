#pragma once
// A large outdoor scene for cascaded shadow maps: a 1 km square ground, thin posts near a
// street-level camera (a row of them on each side of the view, 2.5 m tall and 15 cm wide)
// and a few far buildings, lit by a sun 35 degrees above the horizon. Every shape is an
// axis-aligned box, so the render tests compute its shadows analytically
// (AnalyticShadows.h). One map for all of it spreads 1 km over its texels: a post's shadow
// near the camera is a blob; cascades spend texels where the camera looks closely.
#include "TestScenes.h"

#include <cmath>
#include <string>
#include <vector>

namespace engine::test {

struct OutdoorScene {
    static constexpr double kGroundHalf = 500.0;  // |x|, |z| <= 500, top at y = 0
    std::vector<Aabb> occluders;                  // the posts and buildings (not the ground)
    Scene scene;
    int sunSlot = 0;
};

// `sun`: the sun's extras.shadow settings.
inline OutdoorScene makeOutdoorScene(const nlohmann::json& sun) {
    OutdoorScene out;
    SceneBuilder builder;
    builder.addBox("ground", {-OutdoorScene::kGroundHalf, -0.5, -OutdoorScene::kGroundHalf},
                   {OutdoorScene::kGroundHalf, 0.0, OutdoorScene::kGroundHalf});
    // Posts every 3 m along both kerbs, 3 m left and right of the camera's street, 2 to 29 m
    // ahead of it (the camera looks down -z).
    for (int i = 0; i < 10; ++i)
        for (const double x : {-3.0, 3.0}) {
            const double z = -2.0 - 3.0 * i;
            out.occluders.push_back({{x - 0.075, 0.0, z - 0.075}, {x + 0.075, 2.5, z + 0.075}});
        }
    // Buildings far down the street.
    for (int i = 0; i < 4; ++i) {
        const double x = i % 2 ? 25.0 : -25.0, z = -120.0 - 60.0 * i;
        out.occluders.push_back({{x - 8.0, 0.0, z - 10.0}, {x + 8.0, 20.0 + 5.0 * i, z + 10.0}});
    }
    for (std::size_t i = 0; i < out.occluders.size(); ++i)
        builder.addBox("occluder" + std::to_string(i), out.occluders[i].min, out.occluders[i].max);
    // The sun 35 degrees above the horizon, from the front left, so posts cast shadows
    // across the street toward the camera's side.
    const double elevation = 35.0 * 3.14159265358979323846 / 180.0, azimuth = 0.6;
    const glm::dvec3 toSun(-std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                           -std::cos(elevation) * std::cos(azimuth));
    out.sunSlot = 0;
    builder.addLight("sun", Light::Type::Directional, toSun * 100.0, glm::dvec3(0.0), sun);
    out.scene = builder.build();
    return out;
}

// The street-level camera: eye 1.7 m up, looking down the street, far plane 300 m.
inline FrameCamera outdoorCamera(int width, int height, const glm::dvec3& offset = glm::dvec3(0.0)) {
    FrameCamera camera = cameraLooking(glm::dvec3(0, 1.7, 0) + offset, glm::dvec3(0, 1.0, -20) + offset, width, height);
    camera.projection = glm::perspective(0.9, double(width) / height, 0.1, 300.0);
    return camera;
}

} // namespace engine::test
