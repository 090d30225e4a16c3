// shadowmap-tune's search on made-up costs, no GL: it finds what the full grid would, in
// fewer renders; lockstep renders as many times as the longest list; the offset fit finds
// a known minimum; the current setting stays unless beaten by more than noise.
#include "OffsetFit.h"
#include "Search.h"
#include "SearchSpace.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>

namespace shadowmap_tune {
namespace {

SearchLimits fullLimits() {
    return {{"standard", "woo", "backface"}, {"d16", "d24", "d32f"}, {"nearest", "pcf"}, {512, 1024, 2048, 4096}, {}};
}

// A light whose costs are known in closed form: time grows with texels and with the
// variant's passes; error falls with resolution and depends on variant, format and filter.
// `offsetOptimum`: the polygon offset at which standard's error is lowest.
struct FakeLight {
    double variantError[3];  // standard, woo, backface at 512 texels
    std::array<double, 2> offsetOptimum{1.0, 4.0};
    // The normal offset at which standard's error is lowest; none: it changes nothing.
    std::optional<double> normalOptimum = std::nullopt;  // initialised: brace lists may leave it out
    // Variant volume: no map, exact (error 0) at this time whatever else the candidate says.
    double volumeMs = 3.0;

    Measured measure(const Candidate& c) const {
        const std::string variant = c["variant"];
        if (variant == "volume") {
            // A map's keys would be ignored by the plugin: the search never writes them.
            EXPECT_FALSE(c.contains("resolution") || c.contains("depth_format") || c.contains("filter") ||
                         c.contains("polygon_offset") || c.contains("normal_offset"))
                << c.dump();
            Measured m;
            m.setting = c;
            m.ms = volumeMs;
            m.evaluated = 100000;
            return m;
        }
        const int v = variant == "standard" ? 0 : variant == "woo" ? 1 : 2;
        const double resolution = c["resolution"].get<int>();
        const double texels = resolution * resolution / (512.0 * 512.0);
        Measured m;
        m.setting = c;
        m.ms = texels * (v == 1 ? 2.0 : 1.0) * (c["filter"] == "pcf" ? 1.1 : 1.0) *
               (c["depth_format"] == "d32f" ? 1.2 : c["depth_format"] == "d24" ? 1.05 : 1.0);
        double error = variantError[v] * 512.0 / resolution;
        if (c["filter"] == "pcf") error *= 0.8;
        if (c["depth_format"] == "d16") error *= 1.5;
        if (v == 0) {
            // Acne below the optimum offset, leak above it (log scale, as the lattice).
            const auto offset = c.contains("polygon_offset") ? std::array<double, 2>{c["polygon_offset"][0], c["polygon_offset"][1]}
                                                             : defaultOffset(c);
            const auto distance = [](double a, double b) { return std::abs(std::log2(a + 0.5) - std::log2(b + 0.5)); };
            error += 0.2 * (distance(offset[0], offsetOptimum[0]) + distance(offset[1], offsetOptimum[1]));
            if (normalOptimum)
                error += 0.1 * distance(c.value("normal_offset", shadowmap::ShadowSettings{}.normalOffset), *normalOptimum);
        }
        m.error = error;
        m.evaluated = 100000;
        return m;
    }
};

struct FakeScene {
    std::vector<FakeLight> lights;
    // Each measured time is multiplied by a factor drawn uniformly from [1 - n, 1 + n]
    // (0: exact), as repeated timings of one setting scatter.
    double timeNoise = 0.0;
    std::mt19937 random{1};

    LockstepMeasurer measurer(const std::vector<Candidate>& current) {
        LockstepMeasurer measurer(
            static_cast<int>(lights.size()),
            [this](const std::vector<Candidate>& perLight) {
                std::vector<std::optional<Measured>> out;
                for (std::size_t i = 0; i < perLight.size(); ++i) {
                    out.push_back(lights[i].measure(perLight[i]));
                    out.back()->ms *= std::uniform_real_distribution<double>(1.0 - timeNoise, 1.0 + timeNoise)(random);
                }
                return out;
            },
            [](int, const Candidate&) { return true; });
        for (std::size_t i = 0; i < lights.size(); ++i) measurer.seed(static_cast<int>(i), lights[i].measure(current[i]));
        return measurer;
    }
};

const Candidate kDefault = {{"variant", "standard"}, {"resolution", 2048}, {"depth_format", "d24"}, {"filter", "pcf"}};

// A view's pixels, for expected costs (a volume light's grows with them).
constexpr long kPixels = 160 * 120;

// The exhaustive answer over the grid without offsets: what the search must find.
Measured gridBest(const FakeLight& light, const std::vector<SettingDimension>& space, const Goal& goal) {
    std::optional<Measured> best;
    for (const Candidate& coarse : coarseCandidates(space)) {
        std::vector<Candidate> all = refinedCandidates(space, coarse);
        all.push_back(coarse);
        for (const Candidate& c : all) {
            const Measured m = light.measure(c);
            if (!best || goal.better(m, *best)) best = m;
        }
    }
    return *best;
}

TEST(TuneSearch, FindsTheGridsBestWithinTheBudgetInFarFewerRenders) {
    const std::vector<SettingDimension> space = searchSpace(fullLimits());
    // Light 0: woo is the accurate one; light 1: backface.
    FakeScene scene{{FakeLight{{0.9, 0.3, 0.6}}, FakeLight{{0.9, 0.7, 0.2}}}};
    for (const double budget : {2.5, 5.0, 9.0}) {
        const Goal goal{Goal::Kind::Budget, budget};
        LockstepMeasurer measurer = scene.measurer({kDefault, kDefault});
        const std::vector<LightChoice> choices = searchSettings(measurer, space, goal);
        for (std::size_t i = 0; i < scene.lights.size(); ++i) {
            // A new setting must fit the budget with the timing noise to spare.
            const Measured best = gridBest(scene.lights[i], space, goal.withMargin());
            SCOPED_TRACE("light " + std::to_string(i) + ", budget " + std::to_string(budget));
            // Not offset-fitted (standard never wins here), so the grid's best exactly.
            EXPECT_EQ(choices[i].chosen.setting.dump(), best.setting.dump());
        }
        // The grid per light is 3*3*2*4 = 72 settings without offsets (the coarse pass alone
        // is 18), 1728 with the offset lattice; the search stays under the first.
        EXPECT_LT(measurer.renders(), gridSize(space, 1));
        EXPECT_LT(measurer.renders() * 10, gridSize(space, kOffsetLatticeSize));
        // Nothing is measured twice for a light (a light riding along is not measured again).
        for (std::size_t i = 0; i < scene.lights.size(); ++i) {
            std::set<std::string> seen;
            for (const Measured& m : measurer.measured(static_cast<int>(i)))
                EXPECT_TRUE(seen.insert(m.setting.dump()).second) << m.setting.dump();
        }
    }
}

TEST(TuneSearch, FindsTheCheapestWithinAnError) {
    const std::vector<SettingDimension> space = searchSpace(fullLimits());
    FakeScene scene{{FakeLight{{0.9, 0.3, 0.6}}}};
    const Goal goal{Goal::Kind::MaxError, 0.2};
    LockstepMeasurer measurer = scene.measurer({kDefault});
    const std::vector<LightChoice> choices = searchSettings(measurer, space, goal);
    EXPECT_EQ(choices[0].chosen.setting.dump(), gridBest(scene.lights[0], space, goal).setting.dump());
    EXPECT_TRUE(goal.feasible(choices[0].chosen));
}

// Settings of equal error and cost differ only by timing noise: which one is chosen, and
// what the search measures on the way, must not depend on it, or two runs of the same
// scene (a shard and the single run) choose differently.
TEST(TuneSearch, EqualSettingsAreChosenTheSameWhateverTheTimingNoise) {
    const std::vector<SettingDimension> space = searchSpace(fullLimits());
    // standard (at its default offset, where its error is lowest) and backface tie; woo is
    // twice as slow and worse.
    FakeLight light{{0.5, 0.9, 0.5}};
    light.offsetOptimum = defaultOffset(kDefault);
    // +-15 %: two timings of one cost are at least 0.85/1.15 = 0.74 apart, inside the
    // search's 30 % noise; the test's budget is one nothing exceeds, so errors decide.
    const Goal goal{Goal::Kind::Budget, 1e9};
    std::optional<std::string> first;
    for (unsigned seed = 1; seed <= 20; ++seed) {
        FakeScene scene{{light}, 0.15, std::mt19937{seed}};
        LockstepMeasurer measurer = scene.measurer({kDefault});
        const std::string chosen = searchSettings(measurer, space, goal)[0].chosen.setting.dump();
        std::string measured;
        for (const Measured& m : measurer.measured(0)) measured += m.setting.dump() + "\n";
        SCOPED_TRACE("seed " + std::to_string(seed));
        if (!first) first = chosen + "\n" + measured;
        EXPECT_EQ(chosen + "\n" + measured, *first);
    }
}

TEST(TuneSearch, LockstepRendersAsOftenAsTheLongestList) {
    FakeScene scene{{FakeLight{{0.5, 0.5, 0.5}}, FakeLight{{0.5, 0.5, 0.5}}}};
    LockstepMeasurer measurer = scene.measurer({kDefault, kDefault});
    const Candidate a = {{"variant", "woo"}, {"resolution", 512}, {"depth_format", "d24"}, {"filter", "pcf"}};
    Candidate b = a, c = a;
    b["resolution"] = 1024;
    c["resolution"] = 4096;
    // Light 0: three new candidates; light 1: one new one and its current one (not again).
    measurer.measureLists({{a, b, c}, {kDefault, a}});
    EXPECT_EQ(measurer.renders(), 3);
    EXPECT_EQ(measurer.measured(0).size(), 4u);  // current + 3
    EXPECT_EQ(measurer.measured(1).size(), 2u);  // current + 1
}

TEST(TuneSearch, OffsetFitFindsTheKnownOptimumAndReportsTheDefault) {
    for (const std::array<double, 2> optimum : {std::array<double, 2>{1.0, 4.0}, std::array<double, 2>{4.0, 32.0}}) {
        FakeLight light{{0.3, 0.9, 0.9}};
        light.offsetOptimum = optimum;
        FakeScene scene{{light}};
        LockstepMeasurer measurer = scene.measurer({kDefault});
        const auto fits = fitOffsets(measurer, {kDefault});
        ASSERT_TRUE(fits[0]);
        EXPECT_EQ(fits[0]->fitted.setting["polygon_offset"], nlohmann::json({optimum[0], optimum[1]}));
        EXPECT_EQ(fits[0]->atDefault.setting.dump(), kDefault.dump());
        EXPECT_LT(fits[0]->fitted.error, fits[0]->atDefault.error);
    }
}

TEST(TuneSearch, OffsetFitFindsTheNormalOffsetWithThePolygonOffset) {
    FakeLight light{{0.3, 0.9, 0.9}};
    light.offsetOptimum = {4.0, 32.0};
    light.normalOptimum = 1.0;
    FakeScene scene{{light}};
    LockstepMeasurer measurer = scene.measurer({kDefault});
    const auto fits = fitOffsets(measurer, {kDefault});
    ASSERT_TRUE(fits[0]);
    EXPECT_EQ(fits[0]->fitted.setting["polygon_offset"], nlohmann::json({4.0, 32.0}));
    EXPECT_EQ(fits[0]->fitted.setting["normal_offset"], 1.0);
    EXPECT_EQ(fits[0]->normalOffsets, std::vector<double>(kNormalOffsets.begin(), kNormalOffsets.end()));
}

// A light's own normal offset off the lattice joins it, so the fit starts at the picture the
// light's other candidates were measured with.
TEST(TuneSearch, OffsetFitStartsAtTheLightsOwnNormalOffset) {
    EXPECT_EQ(normalOffsetAxis(0.3), (std::vector<double>{0.0, 0.25, 0.3, 0.5, 1.0, 2.0}));
    EXPECT_EQ(normalOffsetAxis(0.5), std::vector<double>(kNormalOffsets.begin(), kNormalOffsets.end()));
    FakeLight light{{0.3, 0.9, 0.9}};
    light.offsetOptimum = defaultOffset(kDefault);
    light.normalOptimum = 0.3;
    LockstepMeasurer measurer(
        1, [&](const std::vector<Candidate>& perLight) { return std::vector<std::optional<Measured>>{light.measure(perLight[0])}; },
        [](int, const Candidate&) { return true; });
    measurer.seed(0, light.measure(kDefault), 0.3);
    const auto fits = fitOffsets(measurer, {kDefault});
    ASSERT_TRUE(fits[0]);
    EXPECT_EQ(fits[0]->defaultNormalOffset, 0.3);
    EXPECT_EQ(fits[0]->fitted.setting["normal_offset"], 0.3);
}

// filter_taps applies to pcss only: other filters' candidates leave it out (the plugin
// ignores it there), in the grid, the refinement, the current setting and the grid's size.
TEST(TuneSearch, FilterTapsAreADimensionOfPcssOnly) {
    SearchLimits limits{{"standard"}, {"d24"}, {"pcf", "pcss"}, {512, 1024}, {8, 16, 32}};
    const std::vector<SettingDimension> space = searchSpace(limits);
    const std::vector<Candidate> coarse = coarseCandidates(space);
    ASSERT_EQ(coarse.size(), 2u);
    EXPECT_FALSE(coarse[0].contains("filter_taps"));
    EXPECT_EQ(coarse[1]["filter_taps"], 8);  // the fewest first
    EXPECT_EQ(refinedCandidates(space, coarse[0]).size(), 1u);  // 1024
    EXPECT_EQ(refinedCandidates(space, coarse[1]).size(), 3u);  // 1024; 16, 32 taps
    // pcf: 2 resolutions; pcss: 2 x 3 taps; each at every point of the offset lattice.
    EXPECT_EQ(gridSize(space, kOffsetLatticeSize), 8 * kOffsetLatticeSize);
    EXPECT_EQ(candidateOf(space, {{"variant", "standard"}, {"resolution", 512}, {"depth_format", "d24"},
                                  {"filter", "pcf"}, {"filter_taps", 16}}),
              coarse[0]);
    EXPECT_EQ(describe(coarse[1], space), "standard 512 d24 pcss taps8 offset default");
    const auto owned = ownedKeys(space);
    EXPECT_EQ(std::count(owned.begin(), owned.end(), "filter_taps"), 0);
    // pcss reads 4 texels per tap: dearer than pcf's one 2x2 tap, dearer with more taps.
    Candidate more = coarse[1];
    more["filter_taps"] = 16;
    EXPECT_LT(expectedCost(coarse[0], kPixels), expectedCost(coarse[1], kPixels));
    EXPECT_LT(expectedCost(coarse[1], kPixels), expectedCost(more, kPixels));
}

// vsm and evsm are filters of the space like the others, without taps; their expected cost
// counts the moments passes after the depth pass, so at equal error the search prefers the
// filter that renders less (pcf), not the one that reads fewest texels.
TEST(TuneSearch, MomentsFiltersAreCandidatesThatCostTheirPasses) {
    SearchLimits limits{{"standard"}, {"d24"}, {"pcf", "vsm", "evsm"}, {1024, 2048}, {8, 16}};
    const std::vector<SettingDimension> space = searchSpace(limits);
    const std::vector<Candidate> coarse = coarseCandidates(space);
    ASSERT_EQ(coarse.size(), 3u);
    for (const Candidate& candidate : coarse) EXPECT_FALSE(candidate.contains("filter_taps"));
    EXPECT_EQ(describe(coarse[1], space), "standard 1024 d24 vsm offset default");
    EXPECT_EQ(describe(coarse[2], space), "standard 1024 d24 evsm offset default");
    EXPECT_TRUE(usesPolygonOffset(coarse[1]));
    EXPECT_EQ(refinedCandidates(space, coarse[1]).size(), 1u);  // 2048 only: no taps
    const Candidate& pcf = coarse[0];
    const Candidate& vsm = coarse[1];
    const Candidate& evsm = coarse[2];
    // One depth pass and one moments pass: dearer than pcf at its size, cheaper than the
    // next size's depth pass alone (2 x 1024^2 < 2048^2).
    EXPECT_LT(expectedCost(pcf, kPixels), expectedCost(vsm, kPixels));
    EXPECT_EQ(expectedCost(vsm, kPixels), expectedCost(evsm, kPixels));
    Candidate pcf2048 = pcf;
    pcf2048["resolution"] = 2048;
    EXPECT_LT(expectedCost(vsm, kPixels), expectedCost(pcf2048, kPixels));
    // A blur is a second moments pass; mipmaps a trilinear read.
    Candidate blurred = vsm;
    blurred["filter_radius"] = 2;
    EXPECT_LT(expectedCost(vsm, kPixels), expectedCost(blurred, kPixels));
    EXPECT_EQ(expectedCost(blurred, kPixels)[0], 3 * expectedCost(pcf, kPixels)[0]);
    Candidate mipmapped = vsm;
    mipmapped["moments_mipmaps"] = true;
    EXPECT_EQ(expectedCost(mipmapped, kPixels)[0], expectedCost(vsm, kPixels)[0]);
    EXPECT_EQ(expectedCost(mipmapped, kPixels)[1], 2 * expectedCost(pcf, kPixels)[1]);
}

TEST(TuneSearch, KeepsTheCurrentSettingUnlessClearlyBeaten) {
    const Goal budget{Goal::Kind::Budget, 10.0};
    Measured current, choice;
    current.ms = 5.0;
    current.error = 0.5;
    current.evaluated = 100000;  // one pixel: 0.001 %
    choice = current;
    choice.error = 0.5 - 0.0005;  // half a pixel
    EXPECT_FALSE(budget.clearlyBetter(choice, current));
    choice.error = 0.4;
    EXPECT_TRUE(budget.clearlyBetter(choice, current));
    current.ms = 11.0;  // over the budget: anything within it replaces it
    choice.error = 0.9;
    EXPECT_TRUE(budget.clearlyBetter(choice, current));

    const Goal maxError{Goal::Kind::MaxError, 1.0};
    current.ms = 5.0;
    choice = current;
    choice.ms = 4.5;  // 10 % faster: within timing noise
    EXPECT_FALSE(maxError.clearlyBetter(choice, current));
    choice.ms = 2.0;
    EXPECT_TRUE(maxError.clearlyBetter(choice, current));
}

// Variant volume renders no map: one candidate, without resolution, depth format, filter
// or taps (the plugin ignores them there, and would warn about a soft filter), never
// refined, never offset-fitted; its expected cost covers the view, so it grows with the
// image and not with any map's size.
TEST(TuneSearch, VolumeIsOneCandidateWithoutAMapsDimensions) {
    SearchLimits limits{{"standard", "volume"}, {"d24", "d32f"}, {"pcf", "pcss"}, {512, 1024}, {8, 16}};
    const std::vector<SettingDimension> space = searchSpace(limits);
    const std::vector<Candidate> coarse = coarseCandidates(space);
    ASSERT_EQ(coarse.size(), 2u * 2u + 1u);  // standard: 2 formats x 2 filters; volume once
    const Candidate volume = {{"variant", "volume"}};
    EXPECT_EQ(coarse.back(), volume);
    EXPECT_EQ(std::count(coarse.begin(), coarse.end(), volume), 1);
    EXPECT_TRUE(refinedCandidates(space, volume).empty());
    EXPECT_EQ(describe(volume, space), "volume");
    EXPECT_FALSE(usesPolygonOffset(volume));
    // A volume light's settings in effect (the plugin reports a map's too) are that candidate.
    EXPECT_EQ(candidateOf(space, {{"variant", "volume"}, {"resolution", 2048}, {"depth_format", "d24"},
                                  {"filter", "pcss"}, {"filter_taps", 16}}),
              volume);
    // standard: (pcf x 2 resolutions + pcss x 2 resolutions x 2 taps) x 2 formats x lattice;
    // volume: one setting.
    EXPECT_EQ(gridSize(space, kOffsetLatticeSize), 12 * kOffsetLatticeSize + 1);
    // Owned: a volume candidate drops a map's keys the light had, so none lingers.
    const auto owned = ownedKeys(space);
    for (const char* key : {"resolution", "depth_format", "filter"})
        EXPECT_EQ(std::count(owned.begin(), owned.end(), key), 1) << key;
    EXPECT_EQ(expectedCost(volume, kPixels), (std::array<long, 3>{kVolumePixelPasses * kPixels, 1, 4}));
    EXPECT_LT(expectedCost(volume, kPixels), expectedCost(volume, 4 * kPixels));
    Candidate map = coarse.front();
    map["resolution"] = 2048;
    const auto mapCost = expectedCost(map, kPixels);
    EXPECT_EQ(mapCost, expectedCost(map, 4 * kPixels));
}

// With volume allowed, the search chooses it where it is the most accurate within the
// budget, and the best map setting where volume's time is over the budget; the offset fit
// never takes volume as its base (FakeLight::measure checks no offset reaches it).
TEST(TuneSearch, ChoosesVolumeWithinTheBudgetAndAMapBeyondIt) {
    SearchLimits limits = fullLimits();
    limits.variants.push_back("volume");
    const std::vector<SettingDimension> space = searchSpace(limits);
    FakeLight light{{0.9, 0.3, 0.6}};
    light.volumeMs = 3.0;
    for (const double budget : {20.0, 2.0}) {
        FakeScene scene{{light}};
        LockstepMeasurer measurer = scene.measurer({kDefault});
        const Goal goal{Goal::Kind::Budget, budget, kPixels};
        const LightChoice choice = searchSettings(measurer, space, goal)[0];
        SCOPED_TRACE("budget " + std::to_string(budget));
        EXPECT_EQ(choice.chosen.setting.dump(), gridBest(light, space, goal.withMargin()).setting.dump());
        if (budget > light.volumeMs) EXPECT_EQ(choice.chosen.setting["variant"], "volume");
        else EXPECT_NE(choice.chosen.setting["variant"], "volume");
        if (choice.offsetFit) {
            EXPECT_NE(choice.offsetFit->base["variant"], "volume");
        }
    }
}

TEST(TuneSearch, GridCountsOffsetsOnlyForVariantsThatUseOne) {
    const std::vector<SettingDimension> space = searchSpace(fullLimits());
    // standard: 4*3*2 settings x lattice; woo, backface: 2*4*3*2.
    EXPECT_EQ(gridSize(space, kOffsetLatticeSize), 24 * kOffsetLatticeSize + 48);
    EXPECT_TRUE(usesPolygonOffset({{"variant", "standard"}}));
    EXPECT_FALSE(usesPolygonOffset({{"variant", "woo"}}));
}

} // namespace
} // namespace shadowmap_tune
