#pragma once
// What shadowmap-tune chooses among: a list of setting dimensions, each a key of a light's
// extras.shadow with the values worth trying, cheapest first. A new per-light setting (e.g.
// cascades) is one more entry in searchSpace(). The polygon offset is no grid dimension: it
// is fitted per light around the best setting that uses one (OffsetFit.h).
#include <nlohmann/json.hpp>

#include <array>
#include <string>
#include <vector>

namespace shadowmap_tune {

// One light's setting as the tuner writes it: the dimensions' keys, plus polygon_offset
// when explicit. A key left out means the default. nlohmann::json keeps keys sorted, so
// dump() is a canonical name for it.
using Candidate = nlohmann::json;

struct SettingDimension {
    std::string key;                    // as in extras.shadow: "depth_format"
    std::vector<nlohmann::json> values; // cheapest first
    // Searched coarse to fine: the first pass tries only values.front() (the cheapest), the
    // fine pass the other values for the settings the first pass kept. Resolution is one:
    // its time and error move monotonically enough that the cheapest ranks the others.
    bool refined = false;
};

// The values the user allows (--variants, --resolutions, --depth-formats, --filters).
struct SearchLimits {
    std::vector<std::string> variants, depthFormats, filters;
    std::vector<int> resolutions;
};

std::vector<SettingDimension> searchSpace(const SearchLimits& limits);

// Every key the tuner owns in extras.shadow: the dimensions' and polygon_offset. Setting a
// candidate drops these first, so a key the candidate leaves out returns to its default.
std::vector<std::string> ownedKeys(const std::vector<SettingDimension>& space);

// The cartesian product of the non-refined dimensions, refined ones at their first value.
std::vector<Candidate> coarseCandidates(const std::vector<SettingDimension>& space);

// `kept` with each other value of each refined dimension (one dimension at a time).
std::vector<Candidate> refinedCandidates(const std::vector<SettingDimension>& space, const Candidate& kept);

// "woo 1024 d24 pcf [2, 8]": how the report names a candidate (dimension order, then the
// offset when explicit, else "offset default" where the variant uses one).
std::string describe(const Candidate& candidate, const std::vector<SettingDimension>& space);

// True when the candidate's variant draws with a polygon offset (the plugin's settings API:
// its default offset is not zero), i.e. when an offset fit can change anything.
bool usesPolygonOffset(const Candidate& candidate);

// What a setting is expected to cost, from what it draws and reads rather than from a
// measurement: compared lexicographically, the depth texels it renders (resolution squared
// x passes x cascades; woo draws two passes), then the filter's taps, then the depth
// format's bytes. Measured times cannot rank settings of similar cost (one setting's times
// scatter by 30 % and more between runs), and a choice that follows noise differs between
// two runs, or between a shard and the single run; the search ranks by this where errors tie.
std::array<long, 3> expectedCost(const Candidate& candidate);

// The full grid's size per light: the product of the dimensions, counting each setting that
// uses a polygon offset once per offset of the fit's lattice (offsetLatticeSize).
long gridSize(const std::vector<SettingDimension>& space, long offsetLatticeSize);

} // namespace shadowmap_tune
