#include "math/CascadeFit.h"

#include "engine/util/FormatNumber.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowmap {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool usable(const engine::Aabb& box) {
    return !box.empty() && std::isfinite(box.min.x) && std::isfinite(box.min.y) && std::isfinite(box.min.z) &&
           std::isfinite(box.max.x) && std::isfinite(box.max.y) && std::isfinite(box.max.z);
}

// p in the rigid frame L's coordinates, subtracting first so large coordinates cancel.
glm::dvec3 toLocal(const glm::dmat4& frame, const glm::dvec3& world) {
    const glm::dvec3 d = world - glm::dvec3(frame[3]);
    return {glm::dot(glm::dvec3(frame[0]), d), glm::dot(glm::dvec3(frame[1]), d), glm::dot(glm::dvec3(frame[2]), d)};
}

engine::Aabb localBox(const glm::dmat4& frame, const engine::Aabb& world) {
    engine::Aabb out;
    for (int i = 0; i < 8; ++i) out.extend(toLocal(frame, world.corner(i)));
    return out;
}

bool overlapsXY(const engine::Aabb& a, const engine::Aabb& b) {
    return a.min.x <= b.max.x && a.max.x >= b.min.x && a.min.y <= b.max.y && a.max.y >= b.min.y;
}

// The camera's near and far view depths from P_eye (OpenGL clip convention); far may be
// +infinity (an infinite perspective).
void cameraDepthRange(const glm::dmat4& p, double& nearDepth, double& farDepth) {
    if (p[2][3] == 0.0) {  // orthographic: z_ndc = P22 z_e + P32
        nearDepth = (p[3][2] + 1.0) / p[2][2];
        farDepth = (p[3][2] - 1.0) / p[2][2];
        return;
    }
    // perspective: z_ndc = (P22 z_e + P32) / -z_e
    nearDepth = p[3][2] / (p[2][2] - 1.0);
    farDepth = p[2][2] == -1.0 ? kInf : p[3][2] / (p[2][2] + 1.0);
}

// Pads a light-frame box as fitDirectionalLight does: x/y by extentMargin of the largest
// side, depth by depthMargin (at least the x/y pad), so geometry on its faces is inside.
engine::Aabb padded(engine::Aabb box, const FrustumFitOptions& opt) {
    const glm::dvec3 size = box.max - box.min;
    double pad = opt.extentMargin * std::max({size.x, size.y, size.z});
    if (!(pad > 0.0)) pad = 1e-6;
    const double padZ = std::max(opt.depthMargin * size.z, pad);
    box.min -= glm::dvec3(pad, pad, padZ);
    box.max += glm::dvec3(pad, pad, padZ);
    return box;
}

LightView emptyCascade() {
    LightView v;
    v.empty = true;
    v.valid = true;
    return v;
}

}  // namespace

std::vector<double> cascadeSplits(double nearDepth, double farDepth, int count, double lambda) {
    std::vector<double> splits(count + 1);
    for (int i = 0; i <= count; ++i) {
        const double t = double(i) / count;
        const double logarithmic = nearDepth * std::pow(farDepth / nearDepth, t);
        const double uniform = nearDepth + (farDepth - nearDepth) * t;
        splits[i] = lambda * logarithmic + (1.0 - lambda) * uniform;
    }
    // Exact ends, whatever pow rounds to: every receiver depth falls in some slice.
    splits.front() = nearDepth;
    splits.back() = farDepth;
    return splits;
}

bool receiverDepthRange(const CascadeCamera& camera, const std::vector<engine::Aabb>& receivers,
                        double& nearDepth, double& farDepth) {
    double cameraNear, cameraFar;
    cameraDepthRange(camera.projection, cameraNear, cameraFar);
    const glm::dmat4 eye = glm::inverse(camera.eyeToWorld);
    nearDepth = kInf;
    farDepth = -kInf;
    for (const engine::Aabb& box : receivers) {
        if (!usable(box)) continue;
        double lo = kInf, hi = -kInf;
        for (int i = 0; i < 8; ++i) {
            const double depth = -(eye * glm::dvec4(box.corner(i) - glm::dvec3(camera.eyeToWorld[3]), 0.0)).z;
            lo = std::min(lo, depth);
            hi = std::max(hi, depth);
        }
        if (hi < cameraNear || lo > cameraFar) continue;
        nearDepth = std::min(nearDepth, std::max(lo, cameraNear));
        farDepth = std::max(farDepth, std::min(hi, cameraFar));
    }
    return farDepth >= nearDepth;
}

bool shadowedDepthRange(const CascadeCamera& camera, const std::vector<engine::Aabb>& receivers,
                        const CascadeOptions& options, double& nearDepth, double& farDepth) {
    if (!receiverDepthRange(camera, receivers, nearDepth, farDepth)) return false;
    if (options.maxDistance > 0.0) farDepth = std::min(farDepth, options.maxDistance);
    return farDepth >= nearDepth;
}

std::vector<glm::dvec3> frustumSliceCorners(const CascadeCamera& camera, double d0, double d1) {
    const glm::dmat4 inverseProjection = glm::inverse(camera.projection);
    auto unproject = [&](double x, double y, double z) {
        const glm::dvec4 p = inverseProjection * glm::dvec4(x, y, z, 1.0);
        return glm::dvec3(p) / p.w;
    };
    std::vector<glm::dvec3> corners;
    for (const double depth : {d0, d1})
        for (const double y : {-1.0, 1.0})
            for (const double x : {-1.0, 1.0}) {
                // Two finite points of the corner's ray (NDC z -1 and 0 stay finite with an
                // infinite far), followed to eye z = -depth.
                const glm::dvec3 a = unproject(x, y, -1.0), b = unproject(x, y, 0.0);
                const double t = (-depth - a.z) / (b.z - a.z);
                const glm::dvec3 eye = a + t * (b - a);
                // V applied as rotation plus position, so the position is added last, exactly.
                corners.push_back(glm::dvec3(camera.eyeToWorld * glm::dvec4(eye, 0.0)) +
                                  glm::dvec3(camera.eyeToWorld[3]));
            }
    return corners;
}

double quantizedRadius(double radius) {
    constexpr double kSteps = 8.0;  // powers of 2^(1/8): at most 9% more than needed
    return std::exp2(std::ceil(std::log2(radius) * kSteps) / kSteps);
}

double snapToTexel(double value, double texel) { return std::floor(value / texel + 0.5) * texel; }

double cascadeSliceFar(const std::vector<double>& splits, int cascade, const CascadeOptions& options) {
    const bool reaches = !options.stable && cascade + 1 < options.count;
    const double reach = reaches ? options.blend * (splits[cascade + 1] - splits[cascade]) : 0.0;
    return std::min(splits[cascade + 1] + reach, splits.back());
}

CascadeViews fitDirectionalCascades(const engine::LightInstance& instance, const engine::Light&,
                                    const ShadowBounds& bounds, const engine::Aabb& sceneBounds,
                                    const CascadeCamera& camera, const CascadeOptions& options) {
    CascadeViews out;
    glm::dvec3 direction = -glm::dvec3(instance.world[2]);
    const double length = glm::length(direction);
    if (!std::isfinite(length) || !(length > 1e-12)) {
        out.invalidReason = "directional light direction is not a finite non-zero vector";
        return out;
    }
    direction /= length;
    out.valid = true;
    double nearDepth, farDepth;
    if (!shadowedDepthRange(camera, bounds.receivers, options, nearDepth, farDepth)) return out;  // empty
    // A receiver touching the camera's near plane at depth 0 (orthographic) still needs a
    // positive start for the logarithmic part.
    nearDepth = std::max(nearDepth, farDepth * 1e-6);
    out.empty = false;
    out.splits = cascadeSplits(nearDepth, farDepth, options.count, options.lambda);

    // One light frame for every cascade, anchored at the scene's centre (not the camera's
    // view): stable snapping needs texel positions that do not move with the camera.
    engine::Aabb anchorBox = usable(sceneBounds) ? sceneBounds : engine::Aabb{};
    if (anchorBox.empty())
        for (const engine::Aabb& box : bounds.receivers)
            if (usable(box)) anchorBox.extend(box);
    const glm::dmat4 frame = lightToWorldFromDirection(anchorBox.center(), direction);

    std::vector<engine::Aabb> receivers, casters;
    engine::Aabb allReceivers;
    for (const engine::Aabb& box : bounds.receivers)
        if (usable(box)) {
            receivers.push_back(localBox(frame, box));
            allReceivers.extend(receivers.back());
        }
    for (const engine::Aabb& box : bounds.casters)
        if (usable(box)) casters.push_back(localBox(frame, box));
    const engine::Aabb sceneLocal = localBox(frame, anchorBox);

    for (int i = 0; i < options.count; ++i) {
        // With a blend band a fitted cascade reaches past its far split by that band (not past
        // the last split), so the fade into the next cascade samples a map that holds the band.
        // A stable cascade's square around its slice's sphere holds most of the band already,
        // and widening the sphere would coarsen its texels (outdoor sun, blend 0.2: error
        // 0.379 % without the reach, 0.447 % with it); the lookup fades only where the nearer
        // map holds the point (visibility.glsl).
        const std::vector<glm::dvec3> corners =
            frustumSliceCorners(camera, out.splits[i], cascadeSliceFar(out.splits, i, options));
        engine::Aabb slice;
        for (const glm::dvec3& corner : corners) slice.extend(toLocal(frame, corner));
        engine::Aabb box;
        if (options.stable) {
            // The slice's bounding sphere: its radius depends only on the projection and the
            // split depths, not on where the camera is or which way it looks.
            glm::dvec3 centre(0.0);
            for (const glm::dvec3& corner : corners) centre += corner / double(corners.size());
            double radius = 0.0;
            for (const glm::dvec3& corner : corners) radius = std::max(radius, glm::length(corner - centre));
            radius = quantizedRadius(radius);
            const double texel = 2.0 * radius / options.resolution;
            const glm::dvec3 local = toLocal(frame, centre);
            const double x = snapToTexel(local.x, texel), y = snapToTexel(local.y, texel);
            // Depth: the whole scene along the light, padded, so it cannot change either.
            const engine::Aabb depth = padded(sceneLocal, options.fit);
            box.min = {x - radius, y - radius, depth.min.z};
            box.max = {x + radius, y + radius, depth.max.z};
            bool any = false;
            for (const engine::Aabb& receiver : receivers) any = any || overlapsXY(receiver, box);
            out.cascades.push_back(any ? orthographicViewOfBox(frame, {x, y}, {radius, radius}, depth.min.z, depth.max.z,
                                                               options.fit.reversedZ)
                                       : emptyCascade());
            continue;
        }
        // Fitted: the slice's footprint on the visible receivers.
        box.min = glm::max(slice.min, allReceivers.min);
        box.max = glm::min(slice.max, allReceivers.max);
        if (box.min.x > box.max.x || box.min.y > box.max.y) {
            out.cascades.push_back(emptyCascade());
            continue;
        }
        // Depth from the farthest receiver under the footprint (no deeper than the slice
        // reaches) to the nearest-to-the-light caster over it.
        double zBottom = kInf, zTop = -kInf;
        for (const engine::Aabb& receiver : receivers)
            if (overlapsXY(receiver, box)) {
                zBottom = std::min(zBottom, receiver.min.z);
                zTop = std::max(zTop, receiver.max.z);
            }
        if (zTop < zBottom) {
            out.cascades.push_back(emptyCascade());
            continue;
        }
        zBottom = std::max(zBottom, slice.min.z);
        zTop = std::max(zTop, zBottom);
        for (const engine::Aabb& caster : casters)
            if (overlapsXY(caster, box) && caster.max.z > zBottom) zTop = std::max(zTop, caster.max.z);
        box.min.z = zBottom;
        box.max.z = zTop;
        box = padded(box, options.fit);
        out.cascades.push_back(orthographicViewOfBox(frame, glm::dvec2(box.center()), 0.5 * glm::dvec2(box.max - box.min),
                                                     box.min.z, box.max.z, options.fit.reversedZ));
    }
    for (const LightView& view : out.cascades)
        if (!view.valid && out.valid) {
            out.valid = false;
            out.invalidReason = view.invalidReason;
        }
    return out;
}

namespace {

// World units per texel of a view's orthographic map: its wider side over the resolution.
double texelSize(const LightView& view, int resolution) {
    return std::max(2.0 / std::abs(view.projection[0][0]), 2.0 / std::abs(view.projection[1][1])) / resolution;
}

}  // namespace

CascadeNeed cascadeNeed(const engine::LightInstance& instance, const engine::Light& light, const ShadowBounds& bounds,
                        const engine::Aabb& sceneBounds, const CascadeCamera& camera, const CascadeOptions& options,
                        int viewportHeight) {
    CascadeNeed need;
    for (int count = 0; count <= kMaxCascades; ++count) need.texelsPerPixel[count] = need.meanTexel[count] = kInf;
    double nearDepth, farDepth;
    if (viewportHeight <= 0 || !shadowedDepthRange(camera, bounds.receivers, options, nearDepth, farDepth)) return need;
    nearDepth = std::max(nearDepth, farDepth * 1e-6);
    // A pixel's height in world units at the nearest receiver (P11 = cot(fovy / 2), or
    // 2 / height of an orthographic view).
    const bool perspective = camera.projection[2][3] != 0.0;
    const double pixel = (perspective ? nearDepth : 1.0) * 2.0 / (std::abs(camera.projection[1][1]) * viewportHeight);
    // With a shadow distance one map is a slice of the view too (directionalMapIsSliced).
    const int firstSliced = directionalMapIsSliced(1, options.maxDistance) ? 1 : 2;
    if (firstSliced > 1) {
        const LightView single = fitDirectionalLight(instance, light, bounds, options.fit);
        if (single.valid && !single.empty) {
            need.meanTexel[1] = texelSize(single, options.resolution);
            need.texelsPerPixel[1] = need.meanTexel[1] / pixel;
        }
    }
    for (int count = firstSliced; count <= kMaxCascades; ++count) {
        CascadeOptions sliced = options;
        sliced.count = count;
        const CascadeViews views = fitDirectionalCascades(instance, light, bounds, sceneBounds, camera, sliced);
        if (!views.valid) continue;
        // Each slice's texel weighted by its share of the depth range as pixels see it (a
        // perspective pixel grows with depth: log depth; an orthographic one does not).
        double weights = 0.0, logTexels = 0.0;
        for (std::size_t c = 0; c < views.cascades.size(); ++c) {
            const LightView& view = views.cascades[c];
            if (view.empty) continue;
            const double texel = texelSize(view, options.resolution);
            if (!std::isfinite(need.texelsPerPixel[count])) need.texelsPerPixel[count] = texel / pixel;
            const double d0 = views.splits[c], d1 = views.splits[c + 1];
            const double weight = perspective ? std::log(d1 / d0) : d1 - d0;
            weights += weight;
            logTexels += weight * std::log(texel);
        }
        if (weights > 0.0) need.meanTexel[count] = std::exp(logTexels / weights);
    }
    return need;
}

int autoCascadeCount(const CascadeNeed& need, int previous) {
    int count = 1;
    while (count < kMaxCascades && need.texelsPerPixel[count] > kEnoughTexelsPerPixel) {
        const double gain = need.meanTexel[count] / need.meanTexel[count + 1];
        // A cascade already in use stays while it gains kKeepGain; a new one must gain kAddGain.
        if (!(gain >= (count + 1 <= previous ? kKeepGain : kAddGain))) break;
        ++count;
    }
    return count;
}

}  // namespace shadowmap
