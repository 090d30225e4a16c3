#include "OffsetFit.h"

#include "Median.h"

#include "shadowmap/ShadowSettings.h"

#include <algorithm>
#include <cmath>

namespace shadowmap_tune {

namespace {

// At most this many rounds of four renders: from the default [2, 8] the lattice's far
// corners are 6 steps away in either coordinate.
constexpr int kMaxRounds = 8;

// Error differences below this (percent) are no improvement: one pixel of E in a 320x240
// view is 1/76800 = 0.0013 %, so nothing smaller can be a real change.
constexpr double kMinGain = 1e-4;

// A point of one light's lattice: indices into its axes (factor, units, normal offset).
enum Axis { kFactor, kUnits, kNormal, kAxes };
using LatticePoint = std::array<int, kAxes>;

struct Lattice {
    std::array<std::vector<double>, kAxes> axes;

    explicit Lattice(double ownNormalOffset)
        : axes{std::vector<double>(kOffsetFactors.begin(), kOffsetFactors.end()),
               std::vector<double>(kOffsetUnits.begin(), kOffsetUnits.end()), normalOffsetAxis(ownNormalOffset)} {}

    LatticePoint nearest(const std::array<double, kAxes>& values) const {
        LatticePoint point{};
        for (int axis = 0; axis < kAxes; ++axis)
            for (int i = 1; i < static_cast<int>(axes[axis].size()); ++i)
                if (std::abs(axes[axis][i] - values[axis]) < std::abs(axes[axis][point[axis]] - values[axis]))
                    point[axis] = i;
        return point;
    }

    Candidate at(const Candidate& base, const LatticePoint& point) const {
        Candidate candidate = base;
        candidate["polygon_offset"] = {axes[kFactor][point[kFactor]], axes[kUnits][point[kUnits]]};
        candidate["normal_offset"] = axes[kNormal][point[kNormal]];
        return candidate;
    }

    // The polygon offset's neighbours: factor or units one step up or down.
    std::vector<LatticePoint> neighbours(const LatticePoint& point) const {
        std::vector<LatticePoint> out;
        for (const int axis : {kFactor, kUnits})
            for (const int step : {-1, 1}) {
                LatticePoint next = point;
                next[axis] += step;
                if (next[axis] >= 0 && next[axis] < static_cast<int>(axes[axis].size())) out.push_back(next);
            }
        return out;
    }

    // Every normal offset at the point's polygon offset.
    std::vector<LatticePoint> normalLine(const LatticePoint& point) const {
        std::vector<LatticePoint> out;
        for (int i = 0; i < static_cast<int>(axes[kNormal].size()); ++i) {
            LatticePoint next = point;
            next[kNormal] = i;
            out.push_back(next);
        }
        return out;
    }
};

// The setting without the fitted keys: what every point of one fit shares.
Candidate withoutOffsets(Candidate setting) {
    setting.erase("polygon_offset");
    setting.erase("normal_offset");
    return setting;
}

// One light's fit in progress.
struct LightFit {
    Lattice lattice;
    LatticePoint at{};
    std::optional<OffsetFitResult> result;

    Candidate candidate(const LatticePoint& point) const { return lattice.at(result->base, point); }

    // Moves to the best of `points` (all measured through `measurer`) that lowers the error;
    // whether it moved.
    bool moveToBest(const LockstepMeasurer& measurer, int light, const std::vector<LatticePoint>& points) {
        bool moved = false;
        for (const LatticePoint& point : points) {
            const Measured* m = measurer.find(light, candidate(point));
            if (m && m->error < result->fitted.error - kMinGain) {
                result->fitted = *m;
                at = point;
                moved = true;
            }
        }
        return moved;
    }
};

// Measures, for every light still fitting, the points `pointsOf` gives it, in one lockstep.
template <typename PointsOf>
void measurePoints(LockstepMeasurer& measurer, const std::vector<LightFit>& fits, const std::vector<bool>& active,
                   PointsOf pointsOf) {
    std::vector<std::vector<Candidate>> lists(fits.size());
    for (std::size_t light = 0; light < fits.size(); ++light)
        if (active[light])
            for (const LatticePoint& point : pointsOf(fits[light])) lists[light].push_back(fits[light].candidate(point));
    measurer.measureLists(lists);
}

// Round 0: each light's default polygon offset at its own normal offset, explicit and as the
// base measured it (the same pixels). A light that measured nothing (it sees nothing) drops out.
void start(LockstepMeasurer& measurer, std::vector<LightFit>& fits, const std::vector<std::optional<Candidate>>& bases) {
    std::vector<std::vector<Candidate>> lists(fits.size());
    for (std::size_t light = 0; light < fits.size(); ++light) {
        if (!bases[light]) continue;
        LightFit& fit = fits[light];
        const Candidate base = withoutOffsets(*bases[light]);
        const auto offset = defaultOffset(base);
        fit.at = fit.lattice.nearest({offset[0], offset[1], measurer.normalOffset(static_cast<int>(light))});
        fit.result.emplace();
        fit.result->base = base;
        fit.result->defaultNormalOffset = measurer.normalOffset(static_cast<int>(light));
        fit.result->normalOffsets = fit.lattice.axes[kNormal];
        lists[light] = {base, fit.candidate(fit.at)};
    }
    measurer.measureLists(lists);
    for (std::size_t light = 0; light < fits.size(); ++light) {
        LightFit& fit = fits[light];
        if (!fit.result) continue;
        const Measured* atDefault = measurer.find(static_cast<int>(light), fit.result->base);
        const Measured* first = measurer.find(static_cast<int>(light), fit.candidate(fit.at));
        if (!atDefault || !first) {
            fit.result.reset();
            continue;
        }
        fit.result->atDefault = *atDefault;
        fit.result->fitted = *first;
    }
}

void descendPolygonOffset(LockstepMeasurer& measurer, std::vector<LightFit>& fits) {
    std::vector<bool> moving(fits.size());
    for (std::size_t light = 0; light < fits.size(); ++light) moving[light] = fits[light].result.has_value();
    for (int round = 0; round < kMaxRounds && std::count(moving.begin(), moving.end(), true) > 0; ++round) {
        measurePoints(measurer, fits, moving, [](const LightFit& fit) { return fit.lattice.neighbours(fit.at); });
        for (std::size_t light = 0; light < fits.size(); ++light)
            if (moving[light])
                moving[light] = fits[light].moveToBest(measurer, static_cast<int>(light),
                                                       fits[light].lattice.neighbours(fits[light].at));
    }
}

void fitNormalOffset(LockstepMeasurer& measurer, std::vector<LightFit>& fits) {
    std::vector<bool> fitting(fits.size());
    for (std::size_t light = 0; light < fits.size(); ++light) fitting[light] = fits[light].result.has_value();
    measurePoints(measurer, fits, fitting, [](const LightFit& fit) { return fit.lattice.normalLine(fit.at); });
    for (std::size_t light = 0; light < fits.size(); ++light)
        if (fitting[light])
            fits[light].moveToBest(measurer, static_cast<int>(light), fits[light].lattice.normalLine(fits[light].at));
}

// An offset changes no pass and no draw, only the depths written and where the lookup
// compares: every offset of one base costs the same, and their times differ by noise. All
// of them time the base, as their median, so the fit's result and its base compare by error
// alone.
void timeAsBase(const LockstepMeasurer& measurer, int light, OffsetFitResult& result) {
    std::vector<double> times;
    for (const Measured& m : measurer.measured(light))
        if (withoutOffsets(m.setting) == result.base) times.push_back(m.ms);
    result.atDefault.ms = result.fitted.ms = tools::median(times);
}

} // namespace

std::array<double, 2> defaultOffset(const Candidate& base) {
    shadowmap::ShadowSettings settings;
    shadowmap::applySettings(settings, withoutOffsets(base), "shadowmap-tune", "candidate");
    const glm::vec2 offset = settings.effectivePolygonOffset();
    return {offset.x, offset.y};
}

std::vector<double> normalOffsetAxis(double own) {
    std::vector<double> axis(kNormalOffsets.begin(), kNormalOffsets.end());
    if (std::find(axis.begin(), axis.end(), own) == axis.end()) axis.insert(std::upper_bound(axis.begin(), axis.end(), own), own);
    return axis;
}

std::vector<std::optional<OffsetFitResult>> fitOffsets(LockstepMeasurer& measurer,
                                                       const std::vector<std::optional<Candidate>>& bases) {
    std::vector<LightFit> fits;
    for (int light = 0; light < measurer.lights(); ++light) fits.push_back({Lattice(measurer.normalOffset(light)), {}, {}});
    start(measurer, fits, bases);
    descendPolygonOffset(measurer, fits);
    fitNormalOffset(measurer, fits);
    std::vector<std::optional<OffsetFitResult>> results;
    for (int light = 0; light < measurer.lights(); ++light) {
        if (fits[light].result) timeAsBase(measurer, light, *fits[light].result);
        results.push_back(std::move(fits[light].result));
    }
    return results;
}

} // namespace shadowmap_tune
