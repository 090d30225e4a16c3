#include "technique/UnseenShadows.h"

#include "math/CascadeFit.h"

#include "technique/Techniques.h"

#include "engine/scene/FrustumCull.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace shadowmap {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A box as one view of the map sees it: its rectangle and depth range in clip space (x, y,
// z over w), unclipped; everything when a corner is at or behind a perspective light's plane.
struct ClipBox {
    glm::dvec3 min{kInfinity}, max{-kInfinity};

    static ClipBox of(const glm::dmat4& viewProjection, const engine::Aabb& box) {
        ClipBox out;
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 point((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                                   (corner & 4) ? box.max.z : box.min.z);
            const glm::dvec4 clip = viewProjection * glm::dvec4(point, 1.0);
            if (!(clip.w > 0.0)) return {glm::dvec3(-kInfinity), glm::dvec3(kInfinity)};
            const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
            out.min = glm::min(out.min, ndc);
            out.max = glm::max(out.max, ndc);
        }
        return out;
    }
};

// Whether a caster at `caster` can darken some texel a lookup for `receiver` reads. Depth
// grows away from the light in both projections (perspective and orthographic, GL's
// convention; reversed Z is applied in the depth pass, not in this matrix).
bool canShade(const ClipBox& caster, const ClipBox& receiver, double reachNdc) {
    return caster.min.x <= receiver.max.x + reachNdc && caster.max.x >= receiver.min.x - reachNdc &&
           caster.min.y <= receiver.max.y + reachNdc && caster.max.y >= receiver.min.y - reachNdc &&
           caster.min.z <= receiver.max.z;
}

// The visible receivers of one view filed on a grid over its clip-space square, each in the
// cells its widened rectangle covers (what lies beyond the square in the border cells), so
// that a caster is tested only against the receivers in its own cells: every caster against
// every receiver would be millions of tests per view and frame with thousands of instances.
class ReceiverGrid {
public:
    ReceiverGrid(const std::vector<ClipBox>& receivers, double reachNdc) : receivers_(receivers), reach_(reachNdc) {
        for (std::size_t index = 0; index < receivers.size(); ++index) {
            const Cells cells = cellsOf(receivers[index], reachNdc);
            for (int y = cells.y0; y <= cells.y1; ++y)
                for (int x = cells.x0; x <= cells.x1; ++x) cells_[y * kCells + x].push_back(index);
        }
    }

    bool mayShade(const ClipBox& caster) const {
        const Cells cells = cellsOf(caster, 0.0);
        for (int y = cells.y0; y <= cells.y1; ++y)
            for (int x = cells.x0; x <= cells.x1; ++x)
                for (const std::size_t index : cells_[y * kCells + x])
                    if (canShade(caster, receivers_[index], reach_)) return true;
        return false;
    }

private:
    static constexpr int kCells = 32;
    struct Cells {
        int x0, y0, x1, y1;
    };
    // In double before the conversion: an unbounded rectangle clamps to the border.
    static int cell(double ndc) {
        return static_cast<int>(std::clamp(std::floor((ndc + 1.0) * 0.5 * kCells), 0.0, kCells - 1.0));
    }
    static Cells cellsOf(const ClipBox& box, double widen) {
        return {cell(box.min.x - widen), cell(box.min.y - widen), cell(box.max.x + widen), cell(box.max.y + widen)};
    }
    const std::vector<ClipBox>& receivers_;
    double reach_;
    std::array<std::vector<std::size_t>, kCells * kCells> cells_;
};

// The texels around its centre a lookup of this light may read: its filter's reach, the
// normal offset's shift of the receiver, and one for the bilinear footprint's rounding.
double reachTexels(const ShadowSettings& settings) {
    return mapLookupFor(settings).reachTexels(settings) + settings.normalOffset + 1.0;
}

// Whether every caster left out of `rendered` is left out of `now` too.
bool holdsEveryNeededCaster(const std::vector<bool>& rendered, const std::vector<bool>& now) {
    for (std::size_t i = 0; i < rendered.size(); ++i)
        if (rendered[i] && !(i < now.size() && now[i])) return false;
    return true;
}

// The camera's frustum in world space: its six planes (inside: dot(plane, (p, 1)) >= 0)
// and eight corners; false when it has no finite far corner (an infinite far plane).
struct WorldFrustum {
    std::array<glm::dvec4, 6> planes;
    std::array<glm::dvec3, 8> corners;
};

bool worldFrustum(const engine::FrameCamera& camera, WorldFrustum& out) {
    const glm::dmat4 viewProjection = camera.projection * glm::inverse(camera.eyeToWorld);
    const glm::dmat4 rows = glm::transpose(viewProjection);  // rows[i]: row i of the matrix
    for (int axis = 0; axis < 3; ++axis) {
        out.planes[2 * axis] = rows[3] + rows[axis];
        out.planes[2 * axis + 1] = rows[3] - rows[axis];
    }
    const glm::dmat4 clipToWorld = glm::inverse(viewProjection);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec4 world =
            clipToWorld * glm::dvec4((corner & 1) ? 1.0 : -1.0, (corner & 2) ? 1.0 : -1.0, (corner & 4) ? 1.0 : -1.0, 1.0);
        const glm::dvec3 point = glm::dvec3(world) / world.w;
        if (!(std::abs(world.w) > 0.0) || !std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z))
            return false;
        out.corners[corner] = point;
    }
    return true;
}

// The 12 edges of a box (or frustum) by the indices of their corners (bit 0: x, 1: y, 2: z).
constexpr std::array<std::array<int, 2>, 12> kEdges{{{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                                     {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};

// The vertices of `box` cut by the frustum (their convex intersection is the hull of these):
// the corners of each inside the other and where the edges of each cross the faces of the
// other, appended to `out`. None when they do not meet. Inside tests allow a relative
// tolerance, so a point on a face counts.
void appendCutPoints(const engine::Aabb& box, const WorldFrustum& frustum, std::vector<glm::dvec3>& out) {
    const double tolerance = 1e-9 * (1.0 + glm::length(box.max - box.min));
    const auto inFrustum = [&](const glm::dvec3& p) {
        for (const glm::dvec4& plane : frustum.planes)
            if (glm::dot(plane, glm::dvec4(p, 1.0)) < -tolerance * glm::length(glm::dvec3(plane))) return false;
        return true;
    };
    const auto inBox = [&](const glm::dvec3& p) {
        return glm::all(glm::greaterThanEqual(p, box.min - tolerance)) && glm::all(glm::lessThanEqual(p, box.max + tolerance));
    };
    std::array<glm::dvec3, 8> boxCorners;
    for (int corner = 0; corner < 8; ++corner)
        boxCorners[corner] = {(corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                              (corner & 4) ? box.max.z : box.min.z};
    const auto keep = [&](const glm::dvec3& p) {
        if (inFrustum(p) && inBox(p)) out.push_back(p);
    };
    for (const glm::dvec3& corner : boxCorners) keep(corner);
    for (const glm::dvec3& corner : frustum.corners) keep(corner);
    // The box's edges against the frustum's planes.
    for (const auto& edge : kEdges) {
        const glm::dvec3 a = boxCorners[edge[0]], b = boxCorners[edge[1]];
        for (const glm::dvec4& plane : frustum.planes) {
            const double da = glm::dot(plane, glm::dvec4(a, 1.0)), db = glm::dot(plane, glm::dvec4(b, 1.0));
            if ((da < 0.0) != (db < 0.0)) keep(a + (b - a) * (da / (da - db)));
        }
    }
    // The frustum's edges against the box's faces.
    for (const auto& edge : kEdges) {
        const glm::dvec3 a = frustum.corners[edge[0]], b = frustum.corners[edge[1]];
        for (int axis = 0; axis < 3; ++axis)
            for (const double face : {box.min[axis], box.max[axis]}) {
                const double da = a[axis] - face, db = b[axis] - face;
                if ((da < 0.0) != (db < 0.0)) keep(a + (b - a) * (da / (da - db)));
            }
    }
}

// The box around `box` cut by the frustum; empty when they do not meet.
engine::Aabb cutToFrustum(const engine::Aabb& box, const WorldFrustum& frustum) {
    std::vector<glm::dvec3> points;
    appendCutPoints(box, frustum, points);
    engine::Aabb cut;
    for (const glm::dvec3& p : points) cut.extend(p);
    return cut;
}

} // namespace

std::vector<engine::Aabb> visibleReceiverParts(const std::vector<engine::Aabb>& visibleReceivers,
                                               const engine::FrameCamera& camera) {
    WorldFrustum frustum;
    if (!worldFrustum(camera, frustum)) return visibleReceivers;
    std::vector<engine::Aabb> parts;
    for (const engine::Aabb& box : visibleReceivers) {
        const engine::Aabb part = cutToFrustum(box, frustum);
        // The frustum test let the box through: where the cut finds nothing (rounding at a
        // grazing face), the whole box stands in.
        parts.push_back(part.empty() ? box : part);
    }
    return parts;
}

// The frustum's slice between view depths d0 < d1 (along the camera's -Z): its side planes,
// and near and far planes at those depths.
WorldFrustum sliceOf(const WorldFrustum& frustum, const engine::FrameCamera& camera, double d0, double d1) {
    WorldFrustum slice = frustum;
    const glm::dvec3 eye = camera.position(), forward = glm::normalize(-glm::dvec3(camera.eyeToWorld[2]));
    slice.planes[4] = glm::dvec4(forward, -glm::dot(forward, eye) - d0);  // depth >= d0
    slice.planes[5] = glm::dvec4(-forward, glm::dot(forward, eye) + d1);  // depth <= d1
    const std::vector<glm::dvec3> corners = frustumSliceCorners({camera.eyeToWorld, camera.projection}, d0, d1);
    std::copy(corners.begin(), corners.end(), slice.corners.begin());
    return slice;
}

std::vector<glm::dvec3> visibleReceiverPoints(const std::vector<engine::Aabb>& visibleReceivers,
                                              const engine::FrameCamera& camera, std::optional<glm::dvec2> depths) {
    WorldFrustum frustum;
    bool finite = worldFrustum(camera, frustum);
    if (depths) {
        // A slice has a finite far even where the camera's is infinite: its side planes and
        // its own corners are all it needs.
        frustum = sliceOf(frustum, camera, depths->x, depths->y);
        finite = true;
    }
    std::vector<glm::dvec3> points;
    for (const engine::Aabb& box : visibleReceivers) {
        const std::size_t before = points.size();
        if (finite) appendCutPoints(box, frustum, points);
        // As visibleReceiverParts: where the cut finds nothing, the whole box stands in (the
        // box is visible: rounding at a grazing face lost it); a slice may hold none of it.
        if (points.size() == before && !box.empty() && !depths)
            for (int corner = 0; corner < 8; ++corner) points.push_back(box.corner(corner));
    }
    return points;
}

std::vector<bool> castersWithUnseenShadows(const glm::dmat4& viewProjection,
                                           std::span<const engine::Aabb> visibleReceivers,
                                           const engine::Scene& scene, double reachNdc,
                                           bool withNonCastingReceivers) {
    std::vector<ClipBox> receivers;
    receivers.reserve(visibleReceivers.size());
    for (const engine::Aabb& box : visibleReceivers) receivers.push_back(ClipBox::of(viewProjection, box));
    const ReceiverGrid grid(receivers, reachNdc);
    std::vector<bool> unseen(scene.meshInstances.size(), false);
    for (std::size_t i = 0; i < scene.meshInstances.size(); ++i) {
        const engine::MeshInstance& instance = scene.meshInstances[i];
        if (!instance.castShadows && !(withNonCastingReceivers && instance.receiveShadows)) continue;
        if (!engine::boxIntersectsFrustum(viewProjection, instance.worldBounds)) continue;  // culled anyway
        unseen[i] = !grid.mayShade(ClipBox::of(viewProjection, instance.worldBounds));
    }
    return unseen;
}

void planUnseenShadows(LightState& light, const PlanContext& context) {
    LightShadowFrame& plan = light.frame;
    plan.unseenCasters.clear();
    if (!light.settings.cullUnseenCasters || light.settings.variant == Variant::Woo) return;
    const MapProjection& projection = *mapProjection(plan.kind);
    const DepthTechnique* technique = depthTechnique(light.settings.variant);
    const bool withReceivers = technique && technique->drawsNonCastingReceivers();
    const double reachNdc = 2.0 * reachTexels(light.settings) / light.settings.resolution;
    const std::vector<engine::Aabb> receivers = context.visibleReceiverParts
                                                    ? *context.visibleReceiverParts
                                                    : visibleReceiverParts(context.bounds.receivers, context.camera);
    for (const MapLayer& layer : projection.layers(light)) {
        const std::size_t index = layerIndex(layer.layer);
        if (plan.unseenCasters.size() <= index) plan.unseenCasters.resize(index + 1);
        if (!layer.drawsCasters) continue;
        plan.unseenCasters[index] = castersWithUnseenShadows(layer.viewProjection, receivers,
                                                             context.scene, reachNdc, withReceivers);
    }
}

void keepCachedMapsThatHoldTheNeededCasters(LightState& light) {
    LightShadowFrame& plan = light.frame;
    static const std::vector<bool> none;
    auto holds = [&](std::size_t index) {
        const std::vector<bool>& rendered = index < light.renderedUnseen.size() ? light.renderedUnseen[index] : none;
        const std::vector<bool>& now = index < plan.unseenCasters.size() ? plan.unseenCasters[index] : none;
        return holdsEveryNeededCaster(rendered, now);
    };
    if (plan.kind == MapKind::Cascades) {
        bool all = true;
        for (std::size_t c = 0; c < plan.cascadeHits.size(); ++c) {
            if (plan.cascadeHits[c] && !holds(c)) plan.cascadeHits[c] = false;
            all = all && plan.cascadeHits[c];
        }
        plan.cacheHit = all;
        return;
    }
    if (!plan.cacheHit) return;
    for (std::size_t index = 0; index < light.renderedUnseen.size(); ++index)
        if (!holds(index)) plan.cacheHit = false;
}

} // namespace shadowmap
