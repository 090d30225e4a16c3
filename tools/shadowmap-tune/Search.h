#pragma once
// The tuner's search, pure CPU: what to measure and what to choose. The measuring itself
// (GL, truth) comes in as a function, so tests run the search on made-up costs.
//
// Lockstep: lights are independent (each light's passes are timed on their own and its
// error is its own shadow term), so one render measures one candidate of every light.
// Each stage gives every light a list of candidates and the stage takes as many renders as
// the longest list, not the sum.
//
// Stages, per light:
//  1. coarse: every combination of the non-refined dimensions at the cheapest value of the
//     refined ones (resolution);
//  2. prune: only the coarse results on the light's Pareto front of error against expected
//     cost (SearchSpace.h) go on;
//  3. fine: each survivor at the refined dimensions' other values;
//  4. offset: the best setting that uses a polygon offset gets its polygon and normal
//     offsets fitted (OffsetFit.h);
//  5. choose by the goal among everything measured, keeping the light's current setting
//     unless the choice is better by more than measurement noise (so tuning a tuned file
//     changes nothing).
#include "SearchSpace.h"

#include "shadowmap/ShadowSettings.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace shadowmap_tune {

struct Measured {
    Candidate setting;
    double ms = 0.0;  // shadow passes' wall time per frame
    // Percent of the evaluation set, pooled over the views (docs/metrics.md): acne, leak and
    // error against the truth the light is ranked by (evaluation::rankingTruth: the soft
    // truth for a light with a size, else the area truth), what the search ranks by;
    // errorNoEdge against the one-ray truth, away from its shadow edges.
    double acne = 0.0, leak = 0.0, error = 0.0, errorNoEdge = 0.0;
    // Against the soft truth only (0 otherwise): percent mean error over the penumbra, and
    // the penumbra's pixels over all views.
    double penumbraError = 0.0;
    std::size_t evaluatedPenumbra = 0;
    std::size_t evaluated = 0;  // |E| over all views
};

struct Goal {
    enum class Kind { Budget, MaxError };
    Kind kind = Kind::Budget;
    double limit = 0.0;  // ms (Budget) or percent (MaxError)
    // One view's pixels (width x height), what a volume light's passes cover: its expected
    // cost (SearchSpace.h) grows with them, a map's does not.
    long imagePixels = 0;

    bool feasible(const Measured& m) const { return kind == Kind::Budget ? m.ms <= limit : m.error <= limit; }
    // Budget: the lower error within the budget (ties: the lower expected cost, so that
    // timing noise never decides); MaxError: the faster by more than noise within the error
    // (else: lower error, then expected cost). Neither: not better, so of equals the first
    // met wins. A feasible result beats an infeasible one; of two
    // infeasible ones the nearer to feasible wins.
    bool better(const Measured& a, const Measured& b) const;
    // The goal with timing noise taken off a budget: what a new setting must fit, so that a
    // setting near the budget is not chosen in one run and dropped in the next.
    Goal withMargin() const;
    // Whether `choice` improves on the light's current setting by more than noise:
    // errors are deterministic (same settings, same pixels) so one pixel of E is the
    // step; times repeat within kTimeNoise (see Search.cpp).
    bool clearlyBetter(const Measured& choice, const Measured& current) const;
};

// One render: one candidate per light (index = the tuned light's index) in, each light's
// measurement out (nullopt: that light produced none, e.g. nothing in view).
using MeasureRound = std::function<std::vector<std::optional<Measured>>(const std::vector<Candidate>& perLight)>;
// Whether the candidate is a valid setting for that light (with the keys it keeps).
using CandidateCheck = std::function<bool(int light, const Candidate&)>;

// Measures lists of candidates, one per light per render, never the same one twice.
class LockstepMeasurer {
public:
    LockstepMeasurer(int lights, MeasureRound measure, CandidateCheck valid);

    // The light's current setting, measured by the caller's first render, and its own normal
    // offset: every candidate without normal_offset is measured with it (the tuner does not
    // own the key; only the offset fit sets it).
    void seed(int light, const Measured& current, double normalOffset = shadowmap::ShadowSettings{}.normalOffset);
    double normalOffset(int light) const { return normalOffsets_.at(light); }
    // Measures every valid, not yet measured candidate of each light's list. A light whose
    // list has run out rides along with its current setting (its result is not kept again).
    void measureLists(const std::vector<std::vector<Candidate>>& lists);

    const Measured* find(int light, const Candidate& candidate) const;
    const std::vector<Measured>& measured(int light) const { return measured_.at(light); }
    int lights() const { return static_cast<int>(measured_.size()); }
    int renders() const { return renders_; }

private:
    MeasureRound measure_;
    CandidateCheck valid_;
    std::vector<std::vector<Measured>> measured_;
    std::vector<Candidate> current_;
    std::vector<double> normalOffsets_;
    int renders_ = 0;
};

struct OffsetFitResult {
    Candidate base;           // the setting whose offset was fitted (offset at default)
    Measured atDefault;       // base with the variant's default offset
    Measured fitted;          // base with the fitted offsets
    double defaultNormalOffset = 0.0;   // the light's own, which the base was measured with
    std::vector<double> normalOffsets;  // the normal offsets the fit could move through
};

struct LightChoice {
    Measured before, chosen;
    std::optional<OffsetFitResult> offsetFit;
    bool changed = false;  // chosen.setting differs from before.setting
};

// Runs stages 1-5 for every light (the measurer seeded with each light's current setting)
// whose `searched` entry is true (empty: all); the others keep their current setting (they
// ride along in the renders: another shard searches them).
std::vector<LightChoice> searchSettings(LockstepMeasurer& measurer, const std::vector<SettingDimension>& space,
                                        const Goal& goal, const std::vector<bool>& searched = {});

} // namespace shadowmap_tune
