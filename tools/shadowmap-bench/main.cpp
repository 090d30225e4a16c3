// shadowmap-bench: run time against error of the shadow plugin's settings, per light,
// over one or more scenes. Writes results.csv, summary.md and a time/error plot.
#include "ToolMain.h"
#include "ShadowPluginConfig.h"
#include "BenchOptions.h"
#include "GnuplotRunner.h"
#include "ResultsCsv.h"
#include "Shards.h"
#include "SummaryReport.h"
#include "Sweep.h"
#include "TimeErrorPlot.h"

#include "engine/config/EngineConfig.h"
#include "engine/context/GlContext.h"
#include "engine/plugin/PluginHost.h"
#include "engine/util/Error.h"
#include "engine/util/OutputFile.h"
#include "engine/util/ProcessSetup.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <thread>

namespace shadowmap_bench {
namespace {

std::string cpuModel() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    for (std::string line; std::getline(cpuinfo, line);)
        if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos)
            return line.substr(line.find(':') + 2);
    return "unknown CPU";
}

void printProgress(const BenchRow& row, int index, int total) {
    char shimmer[48] = "";
    if (row.shimmer) std::snprintf(shimmer, sizeof shimmer, ", shimmer %.4f%%", *row.shimmer);
    char soft[48] = "";
    if (row.softError) std::snprintf(soft, sizeof soft, ", soft error %.3f%%", *row.softError);
    std::fprintf(stderr, "[%d/%d] %s %s %s: %.2f ms, error %.3f%%%s%s\n", index, total, row.scene.c_str(),
                 row.light.c_str(), row.label().c_str(), row.shadowMs, row.error, soft, shimmer);
}

void writePlot(const std::filesystem::path& out, const std::vector<BenchRow>& rows) {
    const std::filesystem::path script = out / "time_vs_error.gp";
    engine::writeFileAtomically(script, timeErrorPlotScript(rows));
    const std::string temporary = ".time_vs_error.png.tmp";
    const std::string failure = runGnuplot(script, temporary);
    if (!failure.empty()) {
        std::filesystem::remove(out / temporary);
        std::fprintf(stderr, "shadowmap-bench: no plot: %s (wrote %s)\n", failure.c_str(), script.c_str());
        return;
    }
    std::filesystem::rename(out / temporary, out / "time_vs_error.png");
}

// `context` and `host` live in main(), outside the try block that reports errors: an
// exception thrown by plugin code must be read before the plugin is unloaded, and the
// plugin's GL objects must be deleted while the context still exists (host first).
void writeOutputs(const std::filesystem::path& out, const std::vector<BenchRow>& rows, const SweepDescription& sweep) {
    engine::writeFileAtomically(out / "results.csv", resultsCsv(rows));
    engine::writeFileAtomically(out / "summary.md", summaryMarkdown(rows, sweep));
    writePlot(out, rows);
}

std::filesystem::path createOutputFolder(const std::string& folder) {
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error) engine::throwInputError(folder, "", "cannot create the output folder: " + error.message());
    return folder;
}

// --merge: every shard is read and checked before anything is written.
int merge(const BenchOptions& options) {
    std::vector<ShardResult> shards;
    for (const std::string& dir : options.merge) shards.push_back(readShard(dir));
    SweepDescription sweep;
    const std::vector<BenchRow> rows = mergeShards(shards, sweep);
    const std::filesystem::path out = createOutputFolder(options.out);
    writeOutputs(out, rows, sweep);
    std::fprintf(stderr, "shadowmap-bench: merged %zu shards, %zu rows; wrote %s/results.csv, summary.md, time_vs_error.gp/.png\n",
                 shards.size(), rows.size(), options.out.c_str());
    return 0;
}

int run(const BenchOptions& options, std::unique_ptr<engine::GlContext>& context,
        engine::PluginHost& host) {
    if (!options.merge.empty()) return merge(options);
    const auto start = std::chrono::steady_clock::now();
    engine::tuneAllocatorForRendering();
    engine::EngineConfig config = engine::loadEngineConfig(options.config);
    tools::disableShadowMapCaching(config, options.config);
    // Scenes and the output folder are checked before the first (slow) render.
    std::vector<BenchScene> scenes = loadBenchScenes(options, tools::shadowPluginSettings(config));
    const Shard shard{options.shardIndex, options.shardCount};
    keepShardJobs(scenes, shard);
    const std::filesystem::path out = createOutputFolder(options.out);

    context = engine::createEglContext();
    context->makeCurrent();
    host.loadAll(config);
    const SweepRows measured = runSweep(scenes, config.renderer, host.renderPlugins(), options.frames, printProgress);
    const std::vector<BenchRow>& rows = measured.rows;

    SweepDescription sweep{options.width, options.height, options.frames, context->rendererString(),
                           context->versionString(), cpuModel(),
                           static_cast<int>(std::thread::hardware_concurrency()),
                           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
    writeOutputs(out, rows, sweep);
    // Written last: a folder with shard.json is a finished shard.
    if (shard.count > 1) engine::writeFileAtomically(out / "shard.json", shardManifest(shard, sweep, measured.jobRows));
    std::fprintf(stderr, "shadowmap-bench: %zu rows in %.0f s; wrote %s/results.csv, summary.md, time_vs_error.gp/.png\n",
                 rows.size(), sweep.seconds, options.out.c_str());
    return 0;
}

} // namespace
} // namespace shadowmap_bench

int main(int argc, char** argv) {
    return tools::toolMain("shadowmap-bench", shadowmap_bench::benchUsage(), argc, argv,
                           shadowmap_bench::parseBenchOptions,
                           [](const auto& options, tools::ToolSession& session) {
                               return shadowmap_bench::run(options, session.context, session.host);
                           });
}
