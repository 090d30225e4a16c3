#include "Report.h"

#include "engine/util/OutputFile.h"

#include "shadowmap/ShadowSettings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <thread>

namespace stress {

namespace {

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string out = "\"";
    for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
    return out + "\"";
}

std::string fixed(double value, int digits = 3) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", digits, value);
    return text;
}

std::string general(double value) {
    char text[64];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

// Shell-quoted for std::system (single quotes; the paths are ours).
std::string quoted(const std::filesystem::path& path) {
    std::string out = "'";
    for (char c : path.string()) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

constexpr double kPlotFloor = 1e-3;  // percent: where the log-scale plots draw an error of 0

// Where a sweep point goes on the x axis: log axes cannot show 0 (the distance sweep's
// origin is drawn at 1 and labelled 0).
double plotX(const Sweep& sweep, const SweepPoint& point) {
    if (sweep.axis == Axis::Categorical) return point.value;
    return point.value > 0.0 ? point.value : 1.0;
}

std::vector<std::string> lightsOf(const std::vector<Row>& rows, const std::string& sweep) {
    std::vector<std::string> out;
    for (const std::string kind : {"spot", "directional", "point"})
        for (const Row& row : rows)
            if (row.sweep == sweep && row.light == kind) {
                out.push_back(kind);
                break;
            }
    return out;
}

// Series (variant/format) in a stable order: variants, then formats as first seen.
std::vector<std::pair<std::string, std::string>> seriesOf(const std::vector<Row>& rows, const std::string& sweep) {
    std::vector<std::pair<std::string, std::string>> out;
    for (const Row& row : rows)
        if (row.sweep == sweep &&
            std::find(out.begin(), out.end(), std::make_pair(row.variant, row.format)) == out.end())
            out.emplace_back(row.variant, row.format);
    return out;
}

// Markdown table cells: a literal | would end the cell.
std::string tableText(const std::string& text) {
    std::string out;
    for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

// The soft columns of stress.csv: empty for a light without a size.
std::string softFields(const Row& row) {
    if (!row.soft) return ",,";
    return fixed(row.soft->error, 4) + ',' + fixed(row.soft->errorNoEdge, 4) + ',' + fixed(row.soft->penumbraError, 4);
}

// The error the bounds judge (judgedError), "soft " before it for a light with a size.
std::string cell(const Row& row) {
    if (row.nonFiniteShade + row.nonFiniteDepth > 0 || row.nonFiniteStats) return "**NaN**";
    if (row.map == "none") return "no map";
    const JudgedError judged = judgedError(row);
    return (judged.soft ? "soft " : "") + fixed(judged.error, 2) + " (" + fixed(judged.errorNoEdge, 2) + ")";
}

} // namespace

std::string describeMachine() {
    std::string model = "unknown CPU";
    std::ifstream cpuinfo("/proc/cpuinfo");
    for (std::string line; std::getline(cpuinfo, line);)
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            if (colon != std::string::npos) model = line.substr(colon + 2);
            break;
        }
    return "nproc " + std::to_string(std::thread::hardware_concurrency()) + ", " + model;
}

void writeCsv(const std::filesystem::path& path, const std::vector<Row>& rows) {
    std::ostringstream out;
    out << "sweep,light,variant,format,label,value,acne_pct,leak_pct,error_pct,error_noedge_pct,"
           "evaluated_pixels,nonfinite_shade,nonfinite_depth,nonfinite_matrices,map,near,far,"
           "skip_reason,seconds,shimmer_pct,soft_error_pct,soft_error_noedge_pct,penumbra_error_pct\n";
    for (const Row& row : rows)
        out << row.sweep << ',' << row.light << ',' << row.variant << ',' << row.format << ','
            << csvField(row.label) << ',' << general(row.value) << ',' << fixed(row.acne, 4) << ','
            << fixed(row.leak, 4) << ',' << fixed(row.error, 4) << ',' << fixed(row.errorNoEdge, 4) << ','
            << row.evaluated << ',' << row.nonFiniteShade << ',' << row.nonFiniteDepth << ','
            << (row.nonFiniteStats ? 1 : 0) << ',' << row.map << ',' << general(row.nearPlane) << ','
            << (row.farPlane < 0.0 ? std::string("inf") : general(row.farPlane)) << ','
            << csvField(row.skipReason) << ',' << fixed(row.seconds, 3) << ','
            << (row.shimmer < 0.0 ? std::string() : fixed(row.shimmer, 4)) << ','
            << softFields(row) << '\n';
    engine::writeFileAtomically(path, out.str());
}

bool writePlots(const std::filesystem::path& outDir, const std::vector<Sweep>& sweeps,
                const std::vector<Row>& rows, std::string& warning) {
    const std::filesystem::path dir = std::filesystem::absolute(outDir);  // gnuplot runs in it
    if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
        warning = "gnuplot not found (tools/install-deps.sh installs gnuplot-nox): no plots";
        return false;
    }
    const std::filesystem::path plotDir = dir / "plots";
    std::filesystem::create_directories(plotDir);
    // Colour per variant, dash and point per format.
    using shadowmap::toString, shadowmap::Variant, shadowmap::DepthFormat;
    const std::map<std::string, std::string> colours{{toString(Variant::Standard), "#1f77b4"},
                                                     {toString(Variant::Woo), "#d62728"},
                                                     {toString(Variant::Backface), "#2ca02c"},
                                                     {toString(Variant::None), "#7f7f7f"},
                                                     {toString(Variant::Volume), "#9467bd"}};
    const std::map<std::string, std::pair<int, int>> styles{{toString(DepthFormat::D16), {3, 6}},
                                                            {toString(DepthFormat::D24), {1, 7}},
                                                            {toString(DepthFormat::D32F), {2, 5}},
                                                            {reversedZFormat(), {4, 9}}};
    for (const Sweep& sweep : sweeps) {
        const std::vector<std::string> lights = lightsOf(rows, sweep.name);
        if (lights.empty()) continue;
        const auto series = seriesOf(rows, sweep.name);
        std::ostringstream data, script;
        int block = 0;
        std::map<std::pair<std::string, std::pair<std::string, std::string>>, int> blockOf;
        for (const std::string& light : lights)
            for (const auto& s : series) {
                data << "# " << light << " " << s.first << "/" << s.second << "\n";
                for (const SweepPoint& point : sweep.points)
                    for (const Row& row : rows)
                        if (row.sweep == sweep.name && row.light == light && row.variant == s.first &&
                            row.format == s.second && row.label == point.label)
                            data << general(plotX(sweep, point)) << ' '
                                 << (row.map == "none" ? std::string("NaN")
                                                       : general(std::max(judgedError(row).error, kPlotFloor)))
                                 << '\n';
                data << "\n\n";
                blockOf[{light, s}] = block++;
            }
        const std::filesystem::path dataFile = plotDir / (sweep.name + ".dat");
        const std::filesystem::path scriptFile = plotDir / (sweep.name + ".gp");
        const std::filesystem::path png = dir / (sweep.name + ".png");
        engine::writeFileAtomically(dataFile, data.str());

        // Paths relative to the output folder, so the folder can move (docs/stress).
        const std::string dataName = "plots/" + sweep.name + ".dat";
        script << "# shadowmap-stress: " << sweep.title << "\n# remake from the output folder: gnuplot plots/"
               << sweep.name << ".gp\n";
        script << "set terminal pngcairo noenhanced size 1100," << 360 * lights.size() << " font ',9'\n";
        script << "set output '" << png.filename().string() << "'\n";
        script << "set multiplot layout " << lights.size() << ",1 title '" << sweep.title
               << ": error = acne + leak (a light with a size: the soft error), % of the evaluation set'\n";
        // Log y: 0.1% and 20% on one picture; an error of 0 is drawn on the floor.
        script << "set grid\nset key outside right top\nset ylabel 'error % (log; 0 drawn at "
               << general(kPlotFloor) << ")'\nset xlabel '" << sweep.xLabel << "'\n";
        script << "set logscale y\nset yrange [" << general(kPlotFloor) << ":100]\n";
        std::string tics;
        for (const SweepPoint& point : sweep.points)
            tics += (tics.empty() ? "" : ", ") + std::string("'") + point.label + "' " + general(plotX(sweep, point));
        script << "set xtics (" << tics << ")";
        if (sweep.axis == Axis::Categorical) script << " rotate by -15";
        script << "\n";
        double lo = 1e300, hi = -1e300;
        for (const SweepPoint& point : sweep.points) {
            lo = std::min(lo, plotX(sweep, point));
            hi = std::max(hi, plotX(sweep, point));
        }
        if (sweep.axis == Axis::Categorical) {
            script << "unset logscale x\nset xrange [" << lo - 0.5 << ":" << hi + 0.5 << "]\n";
        } else {
            script << "set logscale x\n";
            const double pad = 1.6;
            if (sweep.axis == Axis::LogReversed) script << "set xrange [" << hi * pad << ":" << lo / pad << "]\n";
            else script << "set xrange [" << lo / pad << ":" << hi * pad << "]\n";
        }
        for (const std::string& light : lights) {
            script << "set title '" << light << " light'\nplot ";
            bool first = true;
            for (const auto& s : series) {
                const auto style = styles.count(s.second) ? styles.at(s.second) : std::make_pair(1, 7);
                const std::string colour = colours.count(s.first) ? colours.at(s.first) : "black";
                script << (first ? "" : ", \\\n     ") << "'" << dataName << "' index "
                       << blockOf[{light, s}] << " using 1:2 with "
                       << (sweep.axis == Axis::Categorical ? "points" : "linespoints") << " lc rgb '" << colour
                       << "' dt " << style.first << " pt " << style.second << " lw 1.5 title '" << s.first
                       << (s.second.empty() ? "" : " " + s.second) << "'";
                first = false;
            }
            script << "\n";
        }
        script << "unset multiplot\n";
        engine::writeFileAtomically(scriptFile, script.str());
        const std::filesystem::path log = plotDir / (sweep.name + ".log");
        const std::string command = "cd " + quoted(dir) + " && gnuplot plots/" + sweep.name + ".gp 2>" + quoted(log);
        if (std::system(command.c_str()) != 0) {
            warning = "gnuplot failed on " + scriptFile.string() + " (see " + log.string() + ")";
            return false;
        }
        std::filesystem::remove(log);
    }
    return true;
}

void writeSummary(const std::filesystem::path& path, const RunInfo& info, const std::vector<Sweep>& sweeps,
                  const std::vector<Row>& rows, const std::vector<BoundResult>& bounds, bool plotsWritten) {
    std::ostringstream out;
    int failed = 0;
    for (const BoundResult& bound : bounds) failed += bound.pass() ? 0 : 1;
    out << "# shadowmap-stress " << (info.quick ? "(quick)" : "(full sweep)") << "\n\n";
    out << "- command: `" << info.commandLine << "`\n";
    out << "- machine: " << info.machine << "\n";
    out << "- GL: " << info.glRenderer << "\n";
    out << "- view " << info.width << "x" << info.height << ", shadow maps " << info.resolution
        << "² (PCF 2x2; volume: no map, one case per point, format empty), " << rows.size() << " cases in "
        << fixed(info.seconds, 1) << " s\n";
    out << "- errors: percent of the evaluation set (docs/metrics.md, Embree truth); "
           "tables show `error (error without edge pixels)`, and for a light with a size `soft` the "
           "same against the soft truth (the visible fraction of the light), which the bounds judge it by\n";
    out << "- result: " << (failed ? std::to_string(failed) + " bound(s) FAILED" : std::string("all bounds hold"))
        << "\n\n";

    out << "## Bounds\n\n| bound | requirement | checked | result | worst case |\n|---|---|---|---|---|\n";
    for (const BoundResult& bound : bounds)
        out << "| `" << bound.name << "` | " << tableText(bound.description) << " | " << bound.checked << " | "
            << (bound.checked == 0 ? "not run" : bound.pass() ? "pass" : "**FAIL**") << " | "
            << tableText(bound.worst) << " |\n";
    for (const BoundResult& bound : bounds) {
        if (bound.pass()) continue;
        out << "\n### `" << bound.name << "` failures (" << bound.failures.size() << ")\n\n";
        std::size_t shown = 0;
        for (const std::string& line : bound.failures) {
            if (++shown > 40) {
                out << "- ... " << bound.failures.size() - 40 << " more in stress.csv\n";
                break;
            }
            out << "- " << line << "\n";
        }
    }

    for (const Sweep& sweep : sweeps) {
        const std::vector<std::string> lights = lightsOf(rows, sweep.name);
        if (lights.empty()) continue;
        out << "\n## " << sweep.name << ": " << sweep.title << "\n\n";
        if (!sweep.note.empty()) out << sweep.note << "\n\n";
        if (plotsWritten) out << "![" << sweep.name << "](" << sweep.name << ".png)\n\n";
        std::vector<const SweepPoint*> points;
        for (const SweepPoint& point : sweep.points) points.push_back(&point);
        out << "| light | variant | format |";
        for (const SweepPoint* point : points) out << " " << point->label << " |";
        out << "\n|---|---|---|";
        for (std::size_t i = 0; i < points.size(); ++i) out << "---|";
        out << "\n";
        for (const std::string& light : lights)
            for (const auto& [variant, format] : seriesOf(rows, sweep.name)) {
                bool any = false;
                std::ostringstream line;
                line << "| " << light << " | " << variant << " | " << format << " |";
                for (const SweepPoint* point : points) {
                    const Row* found = nullptr;
                    for (const Row& row : rows)
                        if (row.sweep == sweep.name && row.light == light && row.variant == variant &&
                            row.format == format && row.label == point->label)
                            found = &row;
                    any = any || found;
                    line << " " << (found ? cell(*found) : std::string("")) << " |";
                }
                if (any) out << line.str() << "\n";
            }
    }
    engine::writeFileAtomically(path, out.str());
}

} // namespace stress
