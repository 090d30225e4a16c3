#pragma once
// Shared by the shadow render tests: render a light's shadow mask through the plugin, and
// compare it on floor pixels with visibility computed analytically (segment against boxes).
#include "../../support/TestScenes.h"

#include "engine/plugin/PluginHost.h"
#include "engine/render/Renderer.h"
#include "engine/util/OutputFile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <vector>

namespace engine::test {

// True when the light is visible from p: the segment to it (directional: the ray toward
// it) crosses none of the occluder boxes.
inline bool lightVisibleFrom(const Scene& scene, int slot, const glm::dvec3& p,
                             const std::vector<Aabb>& occluders) {
    const LightInstance& placed = scene.lightInstances[slot];
    const bool directional = scene.lights[placed.light].type == Light::Type::Directional;
    const glm::dvec3 toLight = directional ? -placed.direction() : placed.position() - p;
    const double length = directional ? std::numeric_limits<double>::infinity() : glm::length(toLight);
    const glm::dvec3 direction = glm::normalize(toLight);
    const glm::dvec3 origin = p + direction * 1e-6;
    for (const Aabb& box : occluders) {
        double t0, t1;
        if (intersectBox(origin, direction, box, t0, t1) && t0 < length && t1 > 1e-9) return false;
    }
    return true;
}

struct MaskStats {
    int evaluated = 0;
    int truthLit = 0, truthShadowed = 0;
    int acne = 0;  // truth lit, mask says shadowed
    int leak = 0;  // truth shadowed, mask says lit
    int wrong() const { return acne + leak; }
    double wrongFraction() const { return evaluated ? double(wrong()) / evaluated : 1.0; }
    double acneFraction() const { return truthLit ? double(acne) / truthLit : 0.0; }
    double leakFraction() const { return truthShadowed ? double(leak) / truthShadowed : 0.0; }
};

inline std::vector<std::uint8_t> renderShadowMask(const std::vector<RenderPlugin*>& plugins,
                                           const Scene& scene, const FrameCamera& camera, int slot,
                                           FrameResult* frame = nullptr) {
    Renderer renderer({}, plugins);
    renderer.setScene(scene);
    FrameRequest request;
    request.camera = camera;
    request.shadowMaskSlots = {slot};
    FrameResult result = renderer.renderFrame(request);
    if (frame) *frame = std::move(result);
    return renderer.readShadowMask(slot);
}

// What the analytic model says of one floor point seen along a camera ray: hidden from the
// camera (something else is in front), lit, or shadowed.
enum class FloorTruth { Hidden, Shadowed, Lit };
// floorTruth(cameraRay, t, p): the floor point p = ray.origin + t * ray.direction.
using FloorTruthFunction = std::function<FloorTruth(const Ray& cameraRay, double t, const glm::dvec3& p)>;

// The floor is the plane y = floorY within |x|,|z| < floorHalfExtent; pixels where
// `truthAt` says hidden, where `inside(p)` is false, or within edgeRadius pixels of an
// analytic shadow edge are not evaluated. On any wrong pixel the mask and the truth are
// written to TEST_OUTPUT_DIR, named after the running test.
// The analytic truth per pixel, top row first: 1 lit, 0 shadowed, -1 not evaluated (not
// floor, hidden, or outside `inside`).
inline std::vector<int> floorTruthImage(const FrameCamera& camera, double floorY, double floorHalfExtent,
                                        const std::function<bool(const glm::dvec3&)>& inside,
                                        const FloorTruthFunction& truthAt) {
    const int width = camera.width, height = camera.height;
    std::vector<int> truth(static_cast<std::size_t>(width) * height, -1);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Ray ray = pixelRay(camera, x, y);
            if (ray.direction.y >= 0.0) continue;
            const double t = (floorY - ray.origin.y) / ray.direction.y;
            const glm::dvec3 p = ray.origin + ray.direction * t;
            if (std::abs(p.x) > floorHalfExtent || std::abs(p.z) > floorHalfExtent || !inside(p)) continue;
            const FloorTruth value = truthAt(ray, t, p);
            if (value != FloorTruth::Hidden) truth[y * width + x] = value == FloorTruth::Lit ? 1 : 0;
        }
    return truth;
}

// Calls visit(x, y, p) for every pixel whose camera ray meets the floor plane y = floorY
// within |x|, |z| <= floorHalfExtent, at p (whatever may hide it there).
inline void forEachFloorPixel(const FrameCamera& camera, double floorY, double floorHalfExtent,
                              const std::function<void(int, int, const glm::dvec3&)>& visit) {
    for (int y = 0; y < camera.height; ++y)
        for (int x = 0; x < camera.width; ++x) {
            const Ray ray = pixelRay(camera, x, y);
            if (ray.direction.y >= 0.0) continue;
            const glm::dvec3 p = ray.origin + ray.direction * ((floorY - ray.origin.y) / ray.direction.y);
            if (std::abs(p.x) <= floorHalfExtent && std::abs(p.z) <= floorHalfExtent) visit(x, y, p);
        }
}

// Whether pixel (x, y) of a truth image lies within `radius` pixels of a truth shadow edge.
inline bool nearTruthEdge(const std::vector<int>& truth, int width, int x, int y, int radius) {
    const int value = truth[y * width + x];
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const int other = truth[(y + dy) * width + x + dx];
            if (other >= 0 && other != value) return true;
        }
    return false;
}

inline MaskStats compareFloorMaskWith(const std::vector<std::uint8_t>& mask, const FrameCamera& camera,
                                      double floorY, double floorHalfExtent,
                                      const std::function<bool(const glm::dvec3&)>& inside,
                                      const FloorTruthFunction& truthAt, int edgeRadius = 2) {
    const int width = camera.width, height = camera.height;
    const std::vector<int> truth = floorTruthImage(camera, floorY, floorHalfExtent, inside, truthAt);
    MaskStats stats;
    for (int y = edgeRadius; y < height - edgeRadius; ++y)
        for (int x = edgeRadius; x < width - edgeRadius; ++x) {
            const int value = truth[y * width + x];
            if (value < 0 || nearTruthEdge(truth, width, x, y, edgeRadius)) continue;
            ++stats.evaluated;
            const bool maskLit = mask[y * width + x] >= 128;
            if (value == 1) {
                ++stats.truthLit;
                stats.acne += !maskLit;
            } else {
                ++stats.truthShadowed;
                stats.leak += maskLit;
            }
        }
    std::printf("evaluated %d (lit %d, shadowed %d): acne %d, leak %d, wrong %.3f%%\n",
                stats.evaluated, stats.truthLit, stats.truthShadowed, stats.acne, stats.leak,
                100.0 * stats.wrongFraction());
    if (stats.wrong() > 0) {
        // A parameterized test's name holds '/' (Suite/Name/param): one file name, not folders.
        std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        std::replace(name.begin(), name.end(), '/', '_');
        std::vector<std::uint8_t> truthImage(truth.size());
        for (std::size_t i = 0; i < truth.size(); ++i) truthImage[i] = truth[i] < 0 ? 128 : truth[i] * 255;
        std::filesystem::create_directories(TEST_OUTPUT_DIR);
        writePngAtomically(std::string(TEST_OUTPUT_DIR) + "/" + name + "_mask.png", width, height, 1, mask);
        writePngAtomically(std::string(TEST_OUTPUT_DIR) + "/" + name + "_truth.png", width, height, 1, truthImage);
    }
    return stats;
}

// The truth of a floor among occluder boxes: a floor point is hidden when a box above the
// floor lies in front of it, shadowed when the segment to the light crosses one.
inline FloorTruthFunction boxFloorTruth(const Scene& scene, int slot, const std::vector<Aabb>& occluders,
                                        double floorY) {
    return [&scene, slot, &occluders, floorY](const Ray& ray, double t, const glm::dvec3& p) {
        for (const Aabb& box : occluders) {
            double t0, t1;
            if (box.max.y > floorY + 1e-9 && intersectBox(ray.origin, ray.direction, box, t0, t1) && t0 < t - 1e-9)
                return FloorTruth::Hidden;
        }
        return lightVisibleFrom(scene, slot, p, occluders) ? FloorTruth::Lit : FloorTruth::Shadowed;
    };
}

// compareFloorMaskWith for occluders that are boxes (boxFloorTruth).
inline MaskStats compareFloorMask(const std::vector<std::uint8_t>& mask, const Scene& scene, int slot,
                                  const FrameCamera& camera, const std::vector<Aabb>& occluders,
                                  double floorY, double floorHalfExtent,
                                  const std::function<bool(const glm::dvec3&)>& inside,
                                  int edgeRadius = 2) {
    return compareFloorMaskWith(mask, camera, floorY, floorHalfExtent, inside,
                                boxFloorTruth(scene, slot, occluders, floorY), edgeRadius);
}

// Loads the shadow plugin once per test suite (settings: the config's plugin settings).
class ShadowPluginTest : public GlTest {
protected:
    static void loadPlugin(const nlohmann::json& settings) {
        glTestContext();
        host_ = std::make_unique<PluginHost>();
        host_->load({"shadowmap_plugin", settings}, {ENGINE_PLUGIN_DIR});
    }
    static void TearDownTestSuite() { host_.reset(); }
    static std::vector<RenderPlugin*> plugins() { return host_->renderPlugins(); }

    static inline std::unique_ptr<PluginHost> host_;
};

} // namespace engine::test
