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

struct LatticePoint {
    int factor = 0, units = 0;  // indices into kOffsetFactors, kOffsetUnits
    bool operator==(const LatticePoint&) const = default;
};

template <std::size_t N>
int nearestIndex(const std::array<double, N>& values, double value) {
    int best = 0;
    for (int i = 1; i < static_cast<int>(N); ++i)
        if (std::abs(values[i] - value) < std::abs(values[best] - value)) best = i;
    return best;
}

Candidate withOffset(const Candidate& base, const LatticePoint& point) {
    Candidate candidate = base;
    candidate["polygon_offset"] = {kOffsetFactors[point.factor], kOffsetUnits[point.units]};
    return candidate;
}

std::vector<LatticePoint> neighbours(const LatticePoint& point) {
    std::vector<LatticePoint> out;
    if (point.factor > 0) out.push_back({point.factor - 1, point.units});
    if (point.factor + 1 < static_cast<int>(kOffsetFactors.size())) out.push_back({point.factor + 1, point.units});
    if (point.units > 0) out.push_back({point.factor, point.units - 1});
    if (point.units + 1 < static_cast<int>(kOffsetUnits.size())) out.push_back({point.factor, point.units + 1});
    return out;
}

} // namespace

std::array<double, 2> defaultOffset(const Candidate& base) {
    shadowmap::ShadowSettings settings;
    shadowmap::applySettings(settings, base, "shadowmap-tune", "candidate");
    const glm::vec2 offset = settings.effectivePolygonOffset();
    return {offset.x, offset.y};
}

std::vector<std::optional<OffsetFitResult>> fitOffsets(LockstepMeasurer& measurer,
                                                       const std::vector<std::optional<Candidate>>& bases) {
    const int lights = measurer.lights();
    std::vector<std::optional<OffsetFitResult>> results(lights);
    std::vector<LatticePoint> at(lights);
    std::vector<bool> moving(lights, false);

    // Round 0: the default offset, explicit and as the base measured it (the same pixels).
    std::vector<std::vector<Candidate>> lists(lights);
    for (int light = 0; light < lights; ++light) {
        if (!bases[light]) continue;
        Candidate base = *bases[light];
        base.erase("polygon_offset");
        const auto offset = defaultOffset(base);
        at[light] = {nearestIndex(kOffsetFactors, offset[0]), nearestIndex(kOffsetUnits, offset[1])};
        lists[light] = {base, withOffset(base, at[light])};
        results[light] = OffsetFitResult{base, {}, {}};
    }
    measurer.measureLists(lists);
    for (int light = 0; light < lights; ++light) {
        if (!results[light]) continue;
        const Measured* atDefault = measurer.find(light, results[light]->base);
        const Measured* start = measurer.find(light, withOffset(results[light]->base, at[light]));
        if (!atDefault || !start) {
            results[light].reset();  // nothing measured (e.g. the light sees nothing)
            continue;
        }
        results[light]->atDefault = *atDefault;
        results[light]->fitted = *start;
        moving[light] = true;
    }

    for (int round = 0; round < kMaxRounds; ++round) {
        std::vector<std::vector<Candidate>> next(lights);
        bool any = false;
        for (int light = 0; light < lights; ++light) {
            if (!moving[light]) continue;
            for (const LatticePoint& point : neighbours(at[light]))
                next[light].push_back(withOffset(results[light]->base, point));
            any = true;
        }
        if (!any) break;
        measurer.measureLists(next);
        for (int light = 0; light < lights; ++light) {
            if (!moving[light]) continue;
            moving[light] = false;
            for (const LatticePoint& point : neighbours(at[light])) {
                const Measured* m = measurer.find(light, withOffset(results[light]->base, point));
                if (m && m->error < results[light]->fitted.error - kMinGain) {
                    results[light]->fitted = *m;
                    at[light] = point;
                    moving[light] = true;
                }
            }
        }
    }
    // An offset changes no pass and no draw, only the depths written: every offset of one
    // base costs the same, and their times differ by noise. All of them time the base, as
    // their median, so the fit's result and its base compare by error alone.
    for (int light = 0; light < lights; ++light) {
        if (!results[light]) continue;
        std::vector<double> times;
        for (const Measured& m : measurer.measured(light)) {
            Candidate base = m.setting;
            base.erase("polygon_offset");
            if (base == results[light]->base) times.push_back(m.ms);
        }
        results[light]->atDefault.ms = results[light]->fitted.ms = tools::median(times);
    }
    return results;
}

} // namespace shadowmap_tune
