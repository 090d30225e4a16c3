#include "TimeErrorPlot.h"

#include "ParetoFront.h"

#include "shadowmap/ShadowSettings.h"

#include <algorithm>
#include <cstdio>
#include <iterator>

namespace shadowmap_bench {

namespace {

// gnuplot strings in single quotes: only a quote needs escaping (doubled).
std::string quoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}

// Inside a data block, labels are double-quoted columns.
std::string dataLabel(const std::string& text) {
    std::string out = "\"";
    for (char c : text) out += c == '"' ? '\'' : c;
    return out + "\"";
}

// One gnuplot point shape per variant, in the order the settings API lists the variants
// (standard, woo, backface, none, volume: filled circle, square, triangle, diamond, and
// a filled pentagon drawn larger, since a volume light is one point among a map's grid).
int pointType(const std::string& variant) {
    constexpr int kShapes[] = {7, 5, 9, 13, 15};
    const std::vector<std::string>& variants = shadowmap::settingKey("variant").choices;
    const std::size_t index = std::find(variants.begin(), variants.end(), variant) - variants.begin();
    return kShapes[std::min(index, std::size(kShapes) - 1)];
}

double pointSize(const std::string& variant) { return rendersMap(variant) ? 0.8 : 1.8; }

std::string dataBlock(const std::string& name, const std::vector<BenchRow>& rows) {
    std::string text = "$";
    text += name + " << EOD\n";
    char line[256];
    for (const BenchRow& row : rows) {
        std::snprintf(line, sizeof line, "%.4f %.5f %d ", row.shadowMs, row.rankedError(), pointType(row.setting.variant));
        text += line + dataLabel(row.label());
        std::snprintf(line, sizeof line, " %.1f\n", pointSize(row.setting.variant));
        text += line;
    }
    return text + "EOD\n";
}

// The front points worth a label: each at least 5 % (relative) more accurate than the last
// labelled one. Settings that differ only in depth format often sit on the front a hair
// apart (timing noise), and their labels would print over each other.
std::vector<BenchRow> labelledSteps(const std::vector<BenchRow>& front) {
    std::vector<BenchRow> steps;
    for (const BenchRow& row : front)
        if (steps.empty() || row.rankedError() <= 0.95 * steps.back().rankedError()) steps.push_back(row);
    return steps;
}

std::vector<std::string> sceneNames(const std::vector<LightRows>& lights) {
    std::vector<std::string> scenes;
    for (const LightRows& light : lights)
        if (scenes.empty() || scenes.back() != light.scene) scenes.push_back(light.scene);
    return scenes;
}

} // namespace

std::string timeErrorPlotScript(const std::vector<BenchRow>& rows) {
    const std::vector<LightRows> lights = groupByLight(rows);
    const std::vector<std::string> scenes = sceneNames(lights);
    std::string script = "# Written by shadowmap-bench from results.csv: shadow time against error per scene.\n"
                         "# Run in this folder: gnuplot time_vs_error.gp\n";
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const std::string index = std::to_string(i);
        script += dataBlock("points" + index, lights[i].rows);
        const std::vector<BenchRow> front = paretoFront(lights[i].rows);
        script += dataBlock("front" + index, front);
        script += dataBlock("labels" + index, labelledSteps(front));
    }
    script += "if (!exists('output')) output = 'time_vs_error.png'\n";
    const std::string panels = std::to_string(scenes.size()), height = std::to_string(560 * scenes.size());
    // noenhanced: light names like spot_light must not turn into subscripts.
    script += "set terminal pngcairo noenhanced size 1400," + height + " font 'sans,10'\n";
    script += "set output output\n";
    script += "set multiplot layout " + panels + ",1\n";
    script += "set key outside right top\nset grid\n";
    script += "set xlabel 'shadow passes per frame, ms (median wall time, glFinish)'\n";
    script += "set ylabel 'error, % of evaluated pixels: soft error for a sized light, else area error'\n";
    // Times span three decades (a 512 map of one light to a 2048 woo cube): log x keeps the
    // fast settings, the ones worth choosing, apart.
    script += "set logscale x\nset xrange [*:*]\nset yrange [0:*]\n";
    for (const std::string& scene : scenes) {
        script += "set title " + quoted(scene + ": shadow time against error; lines: Pareto front per light") + "\n";
        std::string plot = "plot ";
        int colour = 0;  // per panel, so each scene's lights get gnuplot's first colours
        for (std::size_t i = 0; i < lights.size(); ++i) {
            if (lights[i].scene != scene) continue;
            const std::string index = std::to_string(i), colourIndex = std::to_string(++colour);
            const std::string lc = " lc " + colourIndex;
            plot += "$points" + index + " using 1:2:5:3 with points pt variable ps variable" + lc + " notitle, \\\n  ";
            plot += "NaN with lines lw 1.5" + lc + " title " + quoted(lights[i].light) + ", \\\n  ";
            plot += "$front" + index + " using 1:2 with lines lw 1.5" + lc + " notitle, \\\n  ";
            plot += "$labels" + index + " using 1:2:4 with labels left offset 0.6,0.4 font ',7' tc lt " + colourIndex +
                    " notitle, \\\n  ";
        }
        // Legend entries for the point shapes of the variants measured (no data: NaN).
        for (const std::string& variant : shadowmap::settingKey("variant").choices)
            if (std::any_of(rows.begin(), rows.end(), [&](const BenchRow& row) { return row.setting.variant == variant; })) {
                char size[16];
                std::snprintf(size, sizeof size, "%.1f", pointSize(variant));
                const std::string title = rendersMap(variant) ? variant : variant + " (no map)";
                plot += "NaN with points pt " + std::to_string(pointType(variant)) + " ps " + size + " lc 'black' title " +
                        quoted(title) + ", ";
            }
        script += plot.substr(0, plot.size() - 2) + "\n";  // drop the last ", "

    }
    return script + "unset multiplot\n";
}

} // namespace shadowmap_bench
