#pragma once
// What shadowmap-tune chooses among: a list of setting dimensions, each a key of a light's
// extras.shadow with the values worth trying, cheapest first. A new per-light setting (e.g.
// cascades) is one more entry in searchSpace(). The polygon and normal offsets are no grid
// dimensions: they are fitted per light around the best setting that uses a polygon offset
// (OffsetFit.h).
#include <nlohmann/json.hpp>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace shadowmap_tune {

// One light's setting as the tuner writes it: the dimensions' keys, plus polygon_offset and
// normal_offset when explicit (the fit's). A key left out means the default, or the light's
// own for a key the tuner does not own (ownedKeys). nlohmann::json keeps keys sorted, so
// dump() is a canonical name for it.
using Candidate = nlohmann::json;

struct SettingDimension {
    std::string key;                    // as in extras.shadow: "depth_format"
    std::vector<nlohmann::json> values; // cheapest first
    // Searched coarse to fine: the first pass tries only values.front() (the cheapest), the
    // fine pass the other values for the settings the first pass kept. Resolution is one:
    // its time and error move monotonically enough that the cheapest ranks the others.
    bool refined = false;
    // How describe() prefixes a value ("taps" in "pcss taps16"); "" where the value says
    // what it is.
    std::string prefix;
    // The dimension applies only where dimension `onlyWith.first` has the value
    // `onlyWith.second` (filter_taps: pcss); elsewhere its key is left out, since the plugin
    // ignores it there and the same picture would be measured once per value. Empty: always.
    std::pair<std::string, nlohmann::json> onlyWith;
    // The opposite: the dimension does not apply where dimension `notWith.first` has the
    // value `notWith.second` (a map's resolution, depth format and filter: variant volume,
    // which renders no map). Empty: never excluded.
    std::pair<std::string, nlohmann::json> notWith;

    bool appliesTo(const Candidate& candidate) const;
};

// The values the user allows (--variants, --resolutions, --depth-formats, --filters,
// --filter-taps). vsm and evsm are filters like the others: they keep the light's own
// filter_radius, bleed_reduction and evsm_exponents (keys the tuner does not own), and a
// light that refuses them (lispsm, a spot or point light's infinite far plane) never gets
// them: the tuner checks every candidate as the plugin would (SceneMeasurer::valid).
struct SearchLimits {
    std::vector<std::string> variants, depthFormats, filters;
    std::vector<int> resolutions;
    std::vector<int> filterTaps;  // pcss candidates only
};

std::vector<SettingDimension> searchSpace(const SearchLimits& limits);

// Every key the tuner owns in extras.shadow: the dimensions' without onlyWith (those with
// notWith too: a volume candidate drops a map's resolution, format and filter, which it does
// not read), and polygon_offset. Setting a candidate drops these first, so a key the
// candidate leaves out returns to its default. The keys only some candidates set are not owned, so a candidate
// without one keeps the light's own value: filter_taps (pcss candidates; a light's wide pcf
// keeps its taps) and normal_offset (the offset fit's, OffsetFit.h).
std::vector<std::string> ownedKeys(const std::vector<SettingDimension>& space);

// A light's setting as `used` (printSettings of the settings in effect) gives it, in the
// space's terms: each dimension's key where the dimension applies (not polygon_offset),
// so that a light's current setting equals the candidate that renders the same picture.
Candidate candidateOf(const std::vector<SettingDimension>& space, const nlohmann::json& used);

// The cartesian product of the non-refined dimensions, refined ones at their first value.
std::vector<Candidate> coarseCandidates(const std::vector<SettingDimension>& space);

// `kept` with each other value of each refined dimension (one dimension at a time).
std::vector<Candidate> refinedCandidates(const std::vector<SettingDimension>& space, const Candidate& kept);

// "standard 1024 d24 pcss taps16 offset [2, 8] normal 0.5": how the report names a candidate
// (dimension order, then the polygon offset when explicit, else "offset default" where the
// variant uses one, then the normal offset when explicit).
std::string describe(const Candidate& candidate, const std::vector<SettingDimension>& space);

// True when the candidate's variant draws with a polygon offset (the plugin's settings API:
// its default offset is not zero), i.e. when an offset fit can change anything.
bool usesPolygonOffset(const Candidate& candidate);

// What a setting is expected to cost, from what it draws and reads rather than from a
// measurement: compared lexicographically, the texels it renders (resolution squared
// x passes x cascades; woo draws two depth passes, vsm and evsm one or, blurred, two
// moments passes after the depth pass), then the texels the filter reads (1 nearest,
// 4 pcf and one bilinear fetch of vsm's or evsm's moments, 8 trilinear, 4 per tap for pcss
// and wide pcf), then the depth format's bytes. Measured times cannot rank settings of similar cost (one setting's times
// scatter by 30 % and more between runs), and a choice that follows noise differs between
// two runs, or between a shard and the single run; the search ranks by this where errors tie.
// A volume light renders no map: its passes cover the view, `imagePixels` (one view's
// width x height) times kVolumePixelPasses, read one visibility texel per pixel, and
// keep a 4-byte depth-stencil buffer.
std::array<long, 3> expectedCost(const Candidate& candidate, long imagePixels);
// The full-view passes a volume light's cost counts (expectedCost). Measured on the
// showcase (shadowmap-bench, llvmpipe, 2 cores) at the tuner's default 1280x720: the spot
// light's volume 7.6 ms against 7.7 ms for its 2048² pcf map, 4 x 921600 = 0.88 x 2048²
// texels. At small views a volume's fixed work (its camera depth pass, the volumes built on
// the CPU) weighs more: at 320x180 it took what a 1024² map takes, counted here as a 480².
inline constexpr long kVolumePixelPasses = 4;

// Every setting of the space: each dimension at each of its values where it applies.
std::vector<Candidate> fullGrid(const std::vector<SettingDimension>& space);

// The full grid's size per light, counting each setting that uses a polygon offset once per
// point of the offset fit's lattice (offsetLatticeSize).
long gridSize(const std::vector<SettingDimension>& space, long offsetLatticeSize);

} // namespace shadowmap_tune
