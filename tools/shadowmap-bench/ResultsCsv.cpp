#include "ResultsCsv.h"

#include "engine/util/FormatNumber.h"

#include <cstdio>

namespace shadowmap_bench {

namespace {

// RFC 4180: a field with a comma, quote or line break is quoted, quotes doubled. Scene and
// light names come from users' files and may hold any of them.
std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::string number(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

// A figure the sweep may not have measured: empty then.
std::string optional(const std::optional<double>& value) { return value ? number(*value, 4) : std::string(); }

// A setting as given (0.0093 rad stays 0.0093): empty when the sweep did not set it.
template <typename T>
std::string optionalSetting(const std::optional<T>& value) {
    return value ? engine::formatNumber(*value) : std::string();
}

// The projection, cascades and stable columns: each empty when the sweep did not set it.
std::string directionalAxes(const ShadowSetting& setting) {
    // Appended piece by piece: GCC 12 reports a false -Wrestrict on "literal" + temporary.
    std::string text = setting.projection ? shadowmap::toString(*setting.projection) : "";
    text += ',';
    if (setting.cascades) text += ShadowSetting::cascadesText(*setting.cascades);
    text += ',';
    if (setting.stable) text += *setting.stable ? "true" : "false";
    return text;
}

} // namespace

std::string resultsCsv(const std::vector<BenchRow>& rows) {
    std::string csv = std::string(kResultsCsvHeader) + "\n";
    for (const BenchRow& row : rows) {
        // Microseconds for times, 1e-4 % for errors (one pixel of a 1280x720 view is 1.1e-4 %).
        // A volume row has no resolution, depth format or filter: their columns are empty.
        const std::string resolution = row.setting.resolution > 0 ? std::to_string(row.setting.resolution) : "";
        csv += csvField(row.scene) + "," + csvField(row.light) + "," + row.setting.variant + "," +
               resolution + "," + row.setting.depthFormat + "," +
               row.setting.filter + "," + number(row.shadowMs, 3) + "," + number(row.frameMs, 3) + "," +
               number(row.acne, 4) + "," + number(row.leak, 4) + "," + number(row.error, 4) + "," +
               number(row.errorNoEdge, 4) + "," + number(row.areaAcne, 4) + "," +
               number(row.areaLeak, 4) + "," + number(row.areaError, 4) + "," +
               optional(row.shimmer) + "," + optional(row.nearError) + "," + optional(row.nearErrorNoEdge) + "," +
               engine::formatNumber(row.lightSize) + "," + optionalSetting(row.setting.filterRadius) + "," +
               optionalSetting(row.setting.filterTaps) + "," + optionalSetting(row.setting.normalOffset) + "," +
               optional(row.softError) + "," + optional(row.softErrorNoEdge) + "," + optional(row.penumbraError) + "," +
               optional(row.texelMean) + "," + optional(row.texelP95) + "," + directionalAxes(row.setting) + "," +
               optionalSetting(row.setting.bleedReduction) + "," + number(row.frameP99Ms, 3) + "," +
               number(row.frameMaxMs, 3) + "\n";
    }
    return csv;
}

} // namespace shadowmap_bench
