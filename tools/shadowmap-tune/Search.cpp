#include "Search.h"

#include "OffsetFit.h"

#include <algorithm>

namespace shadowmap_tune {

namespace {

// Shadow times of one setting vary by roughly +-30 % between runs on the shared 2-core
// machine (README, "Run time against error": load average 5-6); a faster setting must win
// by more than that to replace the current one.
constexpr double kTimeNoise = 0.3;

// Errors closer than this (percent) are equal: one pixel of E in a 320x240 view is
// 1/76800 = 0.0013 %.
constexpr double kErrorEpsilon = 1e-4;

bool lowerError(const Measured& a, const Measured& b) { return a.error < b.error - kErrorEpsilon; }

// Faster by more than timing noise: a time difference smaller than that is no ranking.
bool clearlyFaster(const Measured& a, const Measured& b) { return a.ms < b.ms * (1.0 - kTimeNoise); }

bool cheaper(const Measured& a, const Measured& b, long imagePixels) {
    return expectedCost(a.setting, imagePixels) < expectedCost(b.setting, imagePixels);
}

// The coarse results no other beats in error and expected cost: another as accurate and no
// costlier, better in one. By expected cost, not measured time: an exact front of measured
// times keeps or drops a setting by noise (one frame of one setting measured 0.25 to 2.7 ms
// at 160x120), and a shard and the single run would search different settings. The
// coarse list's order is kept: it is the measuring order, which settles what still ties.
std::vector<Measured> survivors(const std::vector<Measured>& coarse, long imagePixels) {
    const auto beats = [&](const Measured& a, const Measured& b) {
        if (lowerError(b, a) || cheaper(b, a, imagePixels)) return false;
        return lowerError(a, b) || cheaper(a, b, imagePixels);
    };
    std::vector<Measured> out;
    for (const Measured& b : coarse)
        if (std::none_of(coarse.begin(), coarse.end(), [&](const Measured& a) { return beats(a, b); }))
            out.push_back(b);
    return out;
}

} // namespace

bool Goal::better(const Measured& a, const Measured& b) const {
    const bool fa = feasible(a), fb = feasible(b);
    if (fa != fb) return fa;
    if (kind == Kind::Budget) {
        if (!fa) return a.ms < b.ms;
        if (lowerError(a, b) || lowerError(b, a)) return lowerError(a, b);
        return cheaper(a, b, imagePixels);
    }
    if (!fa) return lowerError(a, b);
    if (clearlyFaster(a, b) || clearlyFaster(b, a)) return clearlyFaster(a, b);
    if (lowerError(a, b) || lowerError(b, a)) return lowerError(a, b);
    return cheaper(a, b, imagePixels);
}

Goal Goal::withMargin() const {
    return kind == Kind::Budget ? Goal{kind, limit * (1.0 - kTimeNoise), imagePixels} : *this;
}

bool Goal::clearlyBetter(const Measured& choice, const Measured& current) const {
    if (!feasible(current)) return feasible(choice) || better(choice, current);
    if (!feasible(choice)) return false;
    if (kind == Kind::Budget) {
        // One pixel of the pooled evaluation set, in percent.
        const double pixel = current.evaluated > 0 ? 100.0 / static_cast<double>(current.evaluated) : kErrorEpsilon;
        return choice.error < current.error - std::max(pixel, kErrorEpsilon);
    }
    return clearlyFaster(choice, current);
}

LockstepMeasurer::LockstepMeasurer(int lights, MeasureRound measure, CandidateCheck valid)
    : measure_(std::move(measure)), valid_(std::move(valid)), measured_(lights), current_(lights),
      normalOffsets_(lights, shadowmap::ShadowSettings{}.normalOffset) {}

void LockstepMeasurer::seed(int light, const Measured& current, double normalOffset) {
    current_.at(light) = current.setting;
    normalOffsets_.at(light) = normalOffset;
    measured_.at(light).push_back(current);
}

const Measured* LockstepMeasurer::find(int light, const Candidate& candidate) const {
    for (const Measured& m : measured_.at(light))
        if (m.setting == candidate) return &m;
    return nullptr;
}

void LockstepMeasurer::measureLists(const std::vector<std::vector<Candidate>>& lists) {
    // Each light's queue: its valid candidates not measured yet, in order, without repeats.
    std::vector<std::vector<Candidate>> queues(lights());
    for (int light = 0; light < lights() && light < static_cast<int>(lists.size()); ++light)
        for (const Candidate& candidate : lists[light])
            if (!find(light, candidate) && valid_(light, candidate) &&
                std::find(queues[light].begin(), queues[light].end(), candidate) == queues[light].end())
                queues[light].push_back(candidate);
    std::size_t rounds = 0;
    for (const auto& queue : queues) rounds = std::max(rounds, queue.size());
    for (std::size_t round = 0; round < rounds; ++round) {
        std::vector<Candidate> perLight(lights());
        for (int light = 0; light < lights(); ++light)
            perLight[light] = round < queues[light].size() ? queues[light][round] : current_[light];
        const std::vector<std::optional<Measured>> results = measure_(perLight);
        ++renders_;
        for (int light = 0; light < lights(); ++light) {
            if (round >= queues[light].size() || light >= static_cast<int>(results.size()) || !results[light]) continue;
            Measured m = *results[light];
            m.setting = perLight[light];
            measured_[light].push_back(std::move(m));
        }
    }
}

std::vector<LightChoice> searchSettings(LockstepMeasurer& measurer, const std::vector<SettingDimension>& space,
                                        const Goal& goal, const std::vector<bool>& searched) {
    const int lights = measurer.lights();
    const auto isSearched = [&](int light) { return searched.empty() || searched.at(light); };
    std::vector<LightChoice> choices(lights);
    for (int light = 0; light < lights; ++light) choices[light].before = measurer.measured(light).front();

    // 1. Coarse.
    const std::vector<Candidate> coarse = coarseCandidates(space);
    std::vector<std::vector<Candidate>> coarseLists(lights);
    for (int light = 0; light < lights; ++light)
        if (isSearched(light)) coarseLists[light] = coarse;
    measurer.measureLists(coarseLists);

    // 2-3. Prune to each light's front of error against expected cost, refine the survivors.
    std::vector<std::vector<Candidate>> fine(lights);
    for (int light = 0; light < lights; ++light) {
        if (!isSearched(light)) continue;
        std::vector<Measured> coarseResults;
        for (const Candidate& candidate : coarse)
            if (const Measured* m = measurer.find(light, candidate)) coarseResults.push_back(*m);
        for (const Measured& survivor : survivors(coarseResults, goal.imagePixels)) {
            // The refined dimensions' first values are the cheapest: over the budget there,
            // over it everywhere.
            if (goal.kind == Goal::Kind::Budget && !goal.feasible(survivor)) continue;
            for (Candidate& candidate : refinedCandidates(space, survivor.setting))
                fine[light].push_back(std::move(candidate));
        }
    }
    measurer.measureLists(fine);

    const auto bestOf = [&](int light, const std::function<bool(const Measured&)>& admit,
                            const Goal& by) -> const Measured* {
        const Measured* best = nullptr;
        for (const Measured& m : measurer.measured(light))
            if (admit(m) && (!best || by.better(m, *best))) best = &m;
        return best;
    };

    // 4. Fit the offsets of each light's best setting that draws with a polygon offset.
    std::vector<std::optional<Candidate>> bases(lights);
    for (int light = 0; light < lights; ++light) {
        if (!isSearched(light)) continue;
        const Measured* best = bestOf(light, [](const Measured& m) {
            return usesPolygonOffset(m.setting) && !m.setting.contains("polygon_offset");
        }, goal.withMargin());
        if (best) bases[light] = best->setting;
    }
    const std::vector<std::optional<OffsetFitResult>> fits = fitOffsets(measurer, bases);

    // 5. Choose.
    for (int light = 0; light < lights; ++light) {
        LightChoice& choice = choices[light];
        choice.chosen = choice.before;
        if (!isSearched(light)) continue;
        choice.offsetFit = fits[light];
        // Of the offsets the fit tried only its result competes, in place of its base (the
        // fit starts at the base's offset, so it errs no more): the others differ from it in
        // time by noise alone.
        const auto& fit = choice.offsetFit;
        const auto admit = [&](const Measured& m) {
            if (m.setting == choice.before.setting) return true;
            return !m.setting.contains("polygon_offset") && !(fit && m.setting == fit->base);
        };
        // A new setting must fit the budget with the noise to spare; only when none does is
        // the budget taken at its word.
        const Measured* best = nullptr;
        for (const Goal& by : {goal.withMargin(), goal}) {
            best = bestOf(light, admit, by);
            // The fit's result with its base's median time (OffsetFit.cpp).
            if (fit && (!best || by.better(fit->fitted, *best))) best = &fit->fitted;
            if (best && by.feasible(*best)) break;
        }
        choice.chosen = best && goal.clearlyBetter(*best, choice.before) ? *best : choice.before;
        choice.changed = !(choice.chosen.setting == choice.before.setting);
    }
    return choices;
}

} // namespace shadowmap_tune
