#include "engine/render/FootprintSplit.h"

#include "engine/render/SceneGpu.h"
#include "engine/render/ShadingRegions.h"
#include "engine/scene/FrustumCull.h"
#include "engine/scene/Scene.h"

#include <algorithm>

namespace engine {

namespace {

// Splitting the lit pass by footprints draws a mesh once per region it touches. What that
// costs against what it spares, measured on llvmpipe (2-core EPYC, 1280x720): a shadow lookup
// takes about 4.5 ns of frame per covered pixel (showcase, camera orbiting: 5 ms per light
// over 67 % of the target), a triangle drawn once more about 78 ns (2CylinderEngine: the lit
// pass's binning, 9.4 ms of main-thread time for 121k triangles). So a split must spare
// lookups on more pixels than 17 per triangle it draws again.
constexpr double kPixelsPerRedrawnTriangle = 17.0;
// And it stays small: a light that would split the target into more regions stays out.
// Measured on content/scenes/lamps.gltf (four lamps, camera orbiting, 1280x720): at most 9
// regions limited two lamps (frame 23.0-24.6 -> 21.8-24.4 ms), 32 three (18.5-19.6 ms), 64
// all four in 33 regions and was no faster (20.2-22.7 against 19.3-23.4 ms).
constexpr std::size_t kMaxRegions = 32;

// Whether light `slot`'s shade is looked up in this frame's shaded image and not written
// to the shade cache: only then may a constant stand in for it outside its footprint (the
// cache holds exact shades only).
bool evaluatedUnstored(const ShadeCache::Plan& plan, int slot) {
    const ShadeCache::Source source = plan.sources[slot];
    if (source == ShadeCache::Source::Inline) return true;
    return source == ShadeCache::Source::Moving && (plan.writeArray == 0 || plan.channels[slot] < 0);
}

// The meshes the camera may see, for the footprints: their bounds (what a light can light),
// their footprints and triangles (what drawing one in one more region costs), and a rect
// holding every pixel they may cover.
struct VisibleMeshes {
    std::vector<Aabb> bounds;
    std::vector<PixelRect> footprints;
    std::vector<std::int64_t> triangles;
    PixelRect covered;
};

VisibleMeshes visibleMeshes(const Frame& frame, const glm::dmat4& viewProjection) {
    VisibleMeshes meshes;
    for (const MeshInstance& instance : frame.scene().meshInstances) {
        if (!boxIntersectsFrustum(viewProjection, instance.worldBounds)) continue;
        meshes.bounds.push_back(instance.worldBounds);
        meshes.footprints.push_back(
            projectedFootprint(viewProjection, instance.worldBounds, frame.camera().width, frame.camera().height));
        meshes.covered = enclosing(meshes.covered, meshes.footprints.back());
        std::int64_t triangles = 0;
        for (const SceneGpu::Primitive& primitive : frame.gpu().primitives(instance)) triangles += primitive.indexCount / 3;
        meshes.triangles.push_back(triangles);
    }
    return meshes;
}

// A light whose lookups a footprint could spare on `sparedPixels` of the covered rect.
struct LimitCandidate {
    int slot;
    PixelRect footprint;
    std::int64_t sparedPixels;
};

// The candidates that join the split, most pixels spared first, while it stays within
// kMaxRegions and spares more lookups than the meshes it draws more than once cost; `split`
// receives their regions (bit i of a region's set: the i-th light returned).
std::vector<LimitCandidate> lightsWorthLimiting(std::vector<LimitCandidate> candidates, const VisibleMeshes& meshes,
                                                int width, int height, std::vector<ShadingRegion>& split) {
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const LimitCandidate& a, const LimitCandidate& b) { return a.sparedPixels > b.sparedPixels; });
    std::vector<LimitCandidate> limited;
    std::int64_t spared = 0;
    for (const LimitCandidate& candidate : candidates) {
        std::vector<PixelRect> footprints;
        for (const LimitCandidate& light : limited) footprints.push_back(light.footprint);
        footprints.push_back(candidate.footprint);
        std::vector<ShadingRegion> trial = splitByFootprints(footprints, width, height);
        if (trial.size() > kMaxRegions) continue;
        std::int64_t redrawnTriangles = 0;
        for (std::size_t i = 0; i < meshes.footprints.size(); ++i) {
            const auto touched = std::count_if(trial.begin(), trial.end(), [&](const ShadingRegion& region) {
                return region.rect.intersects(meshes.footprints[i]);
            });
            redrawnTriangles += std::max<std::int64_t>(touched - 1, 0) * meshes.triangles[i];
        }
        if (double(spared + candidate.sparedPixels) <= double(redrawnTriangles) * kPixelsPerRedrawnTriangle) continue;
        spared += candidate.sparedPixels;
        limited.push_back(candidate);
        split = std::move(trial);
    }
    return limited;
}

} // namespace

ShadeCache::Plan withoutLookups(ShadeCache::Plan plan, const std::vector<int>& slots) {
    for (const int slot : slots) {
        plan.sources[slot] = ShadeCache::Source::Constant;
        plan.constants[slot] = 1.0f;
    }
    return plan;
}

std::vector<int> footprintLimitableLights(const Scene& scene, const ShadeCache::Plan& plan) {
    std::vector<int> slots;
    for (int slot = 0; slot < static_cast<int>(plan.sources.size()); ++slot)
        if (evaluatedUnstored(plan, slot) &&
            scene.lights[scene.lightInstances[slot].light].type != Light::Type::Directional)
            slots.push_back(slot);
    return slots;
}

FootprintSplit splitByLightFootprints(const Frame& frame, const ShadeCache::Plan& shadePlan) {
    const FrameCamera& camera = frame.camera();
    FootprintSplit result;
    result.regions = {{PixelRect::target(camera.width, camera.height), shadePlan}};
    const Scene& scene = frame.scene();
    const glm::dmat4 viewProjection = camera.projection * glm::inverse(camera.eyeToWorld);
    const VisibleMeshes meshes = visibleMeshes(frame, viewProjection);
    std::vector<LimitCandidate> candidates;
    for (int slot = 0; slot < static_cast<int>(shadePlan.sources.size()); ++slot) {
        if (!evaluatedUnstored(shadePlan, slot)) continue;
        const LightInstance& placed = scene.lightInstances[slot];
        const PixelRect footprint = lightFootprint(scene.lights[placed.light], placed, meshes.bounds, viewProjection,
                                                   camera.width, camera.height);
        const std::int64_t spared = meshes.covered.area() - intersection(meshes.covered, footprint).area();
        if (spared > 0) candidates.push_back({slot, footprint, spared});
    }
    std::vector<ShadingRegion> split;
    const std::vector<LimitCandidate> limited = lightsWorthLimiting(candidates, meshes, camera.width, camera.height, split);
    if (limited.empty()) return result;
    result.regions.clear();
    for (const ShadingRegion& region : split) {
        std::vector<int> outside;
        for (std::size_t i = 0; i < limited.size(); ++i)
            if (!(region.footprints & (1u << i))) outside.push_back(limited[i].slot);
        result.regions.emplace_back(region.rect, withoutLookups(shadePlan, outside));
    }
    for (const LimitCandidate& light : limited) result.limitedLights.push_back(light.slot);
    std::sort(result.limitedLights.begin(), result.limitedLights.end());
    return result;
}

} // namespace engine
