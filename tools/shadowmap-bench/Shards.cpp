#include "Shards.h"

#include "OptionValues.h"
#include "ResultsCsv.h"

#include "engine/util/Error.h"
#include "engine/util/InputFile.h"
#include "shadowmap/ShadowSettings.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace shadowmap_bench {

namespace {

// What --merge reads of a shard's folder; a file missing means the shard did not finish.
std::string readShardFile(const std::filesystem::path& path) {
    return engine::readWholeFile(path, "it (is the folder a finished shard?)");
}

// One record of RFC 4180 CSV from `at` (quoted fields may hold commas, quotes, line breaks).
std::vector<std::string> readRecord(const std::string& text, std::size_t& at) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (; at < text.size(); ++at) {
        const char c = text[at];
        if (quoted) {
            if (c == '"' && at + 1 < text.size() && text[at + 1] == '"') {
                fields.back() += '"';
                ++at;
            } else if (c == '"') quoted = false;
            else fields.back() += c;
        } else if (c == '"') quoted = true;
        else if (c == ',') fields.emplace_back();
        else if (c == '\n') {
            ++at;
            break;
        } else if (c != '\r') fields.back() += c;
    }
    return fields;
}

double number(const std::string& text, const std::string& file, int line) {
    std::size_t used = 0;
    double value = 0.0;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != text.size())
        engine::throwInputError(file, "line " + std::to_string(line), "\"" + text + "\" is not a number");
    return value;
}

// A field that must be one of `known`.
std::string choice(const std::string& text, const std::vector<std::string>& known, const std::string& file, int line) {
    if (std::find(known.begin(), known.end(), text) != known.end()) return text;
    std::string list;
    for (const std::string& item : known) list += (list.empty() ? "" : ", ") + item;
    engine::throwInputError(file, "line " + std::to_string(line), "\"" + text + "\" is none of " + list);
}

shadowmap::Projection projection(const std::string& text, const std::string& file, int line) {
    const std::string name = choice(text, shadowmap::settingKey("projection").choices, file, line);
    return name == shadowmap::toString(shadowmap::Projection::Lispsm) ? shadowmap::Projection::Lispsm
                                                                       : shadowmap::Projection::Uniform;
}

} // namespace

void keepShardJobs(std::vector<BenchScene>& scenes, const Shard& shard) {
    long job = 0;
    for (BenchScene& scene : scenes) {
        std::vector<ShadowSetting> kept;
        for (const ShadowSetting& setting : scene.settings)
            if (job++ % shard.count == shard.index - 1) kept.push_back(setting);
        scene.settings = std::move(kept);
    }
}

std::string shardManifest(const Shard& shard, const SweepDescription& sweep, const std::vector<int>& jobRows) {
    const nlohmann::json manifest = {{"shard", shard.index}, {"of", shard.count},
                                     {"width", sweep.width}, {"height", sweep.height},
                                     {"frames", sweep.frames}, {"gl_renderer", sweep.glRenderer},
                                     {"gl_version", sweep.glVersion}, {"cpu", sweep.cpuModel},
                                     {"cores", sweep.cores}, {"seconds", sweep.seconds},
                                     {"job_rows", jobRows}};
    return manifest.dump(2) + "\n";
}

std::vector<BenchRow> parseResultsCsv(const std::string& text, const std::string& file) {
    std::size_t at = 0;
    int line = 1;
    std::vector<std::string> header = readRecord(text, at);
    std::string joined;
    for (const std::string& field : header) joined += (joined.empty() ? "" : ",") + field;
    if (joined != kResultsCsvHeader) engine::throwInputError(file, "line 1", "not the header of shadowmap-bench's results.csv");
    std::vector<BenchRow> rows;
    while (at < text.size()) {
        ++line;
        const std::vector<std::string> f = readRecord(text, at);
        if (f.size() != kResultsCsvColumns)
            engine::throwInputError(file, "line " + std::to_string(line),
                                    std::to_string(f.size()) + " fields, expected " +
                                        std::to_string(kResultsCsvColumns));
        BenchRow row;
        row.scene = f[0];
        row.light = f[1];
        // A volume row's resolution is empty (ResultsCsv.h): 0, as the sweep made it.
        const bool noMap = !rendersMap(f[2]) && f[3].empty();
        row.setting = {f[2], noMap ? 0 : static_cast<int>(number(f[3], file, line)), f[4], f[5]};
        row.shadowMs = number(f[6], file, line);
        row.frameMs = number(f[7], file, line);
        row.frameP99Ms = number(f[31], file, line);
        row.frameMaxMs = number(f[32], file, line);
        row.acne = number(f[8], file, line);
        row.leak = number(f[9], file, line);
        row.error = number(f[10], file, line);
        row.errorNoEdge = number(f[11], file, line);
        row.areaAcne = number(f[12], file, line);
        row.areaLeak = number(f[13], file, line);
        row.areaError = number(f[14], file, line);
        row.lightSize = number(f[18], file, line);
        for (auto [field, figure] : {std::pair{15, &row.shimmer}, {16, &row.nearError}, {17, &row.nearErrorNoEdge},
                                     {19, &row.setting.filterRadius}, {21, &row.setting.normalOffset},
                                     {30, &row.setting.bleedReduction},
                                     {22, &row.softError}, {23, &row.softErrorNoEdge}, {24, &row.penumbraError},
                                     {25, &row.texelMean}, {26, &row.texelP95}})
            if (!f[field].empty()) *figure = number(f[field], file, line);
        if (!f[20].empty()) row.setting.filterTaps = static_cast<int>(number(f[20], file, line));
        if (!f[27].empty()) row.setting.projection = projection(f[27], file, line);
        if (!f[28].empty())
            row.setting.cascades =
                f[28] == "auto" ? shadowmap::kAutoCascades : static_cast<int>(number(f[28], file, line));
        if (!f[29].empty()) row.setting.stable = choice(f[29], {"true", "false"}, file, line) == "true";
        rows.push_back(std::move(row));
    }
    return rows;
}

ShardResult readShard(const std::filesystem::path& dir) {
    const std::filesystem::path manifestPath = dir / "shard.json";
    const nlohmann::json manifest = nlohmann::json::parse(readShardFile(manifestPath), nullptr, false);
    ShardResult result;
    try {
        result.shard = {manifest.at("shard").get<int>(), manifest.at("of").get<int>()};
        result.sweep = {manifest.at("width").get<int>(),         manifest.at("height").get<int>(),
                        manifest.at("frames").get<int>(),        manifest.at("gl_renderer").get<std::string>(),
                        manifest.at("gl_version").get<std::string>(), manifest.at("cpu").get<std::string>(),
                        manifest.at("cores").get<int>(),         manifest.at("seconds").get<double>()};
        result.jobRows = manifest.at("job_rows").get<std::vector<int>>();
    } catch (const nlohmann::json::exception& error) {
        engine::throwInputError(manifestPath.string(), "", std::string("not a shard manifest: ") + error.what());
    }
    const std::filesystem::path csv = dir / "results.csv";
    result.rows = parseResultsCsv(readShardFile(csv), csv.string());
    const long jobRows = std::accumulate(result.jobRows.begin(), result.jobRows.end(), 0L);
    const bool negative = std::any_of(result.jobRows.begin(), result.jobRows.end(), [](int rows) { return rows < 0; });
    if (negative || jobRows != static_cast<long>(result.rows.size()))
        engine::throwInputError(manifestPath.string(), "job_rows",
                                "add up to " + std::to_string(jobRows) + " rows, and " + csv.string() + " has " +
                                    std::to_string(result.rows.size()));
    return result;
}

std::vector<BenchRow> mergeShards(const std::vector<ShardResult>& shards, SweepDescription& sweep) {
    if (shards.empty()) throw engine::InputError("--merge: no shard folders given");
    const int count = shards.front().shard.count;
    std::vector<const ShardResult*> byIndex(count, nullptr);
    for (const ShardResult& shard : shards) {
        if (shard.shard.count != count)
            throw engine::InputError("--merge: shards of different sweeps (of " + std::to_string(count) + " and of " +
                                     std::to_string(shard.shard.count) + ")");
        const ShardResult*& slot = byIndex.at(shard.shard.index - 1);
        if (slot) throw engine::InputError("--merge: shard " + std::to_string(shard.shard.index) + " given twice");
        slot = &shard;
    }
    for (int k = 0; k < count; ++k)
        if (!byIndex[k])
            throw engine::InputError("--merge: shard " + std::to_string(k + 1) + "/" + std::to_string(count) + " missing");

    // Each shard's rows in jobs (its manifest's rows per job), dealt back round-robin: job j
    // of the single run is job j / N of shard j % N + 1.
    std::vector<std::vector<std::vector<BenchRow>>> jobs(count);
    for (int k = 0; k < count; ++k) {
        auto row = byIndex[k]->rows.begin();
        for (int size : byIndex[k]->jobRows) {
            jobs[k].emplace_back(row, row + size);
            row += size;
        }
    }
    std::vector<BenchRow> rows;
    for (std::size_t round = 0;; ++round) {
        bool any = false;
        for (int k = 0; k < count; ++k)
            if (round < jobs[k].size()) {
                any = true;
                rows.insert(rows.end(), jobs[k][round].begin(), jobs[k][round].end());
            }
        if (!any) break;
    }
    sweep = byIndex[0]->sweep;
    sweep.seconds = 0.0;
    for (const ShardResult& shard : shards) sweep.seconds += shard.sweep.seconds;
    return rows;
}

} // namespace shadowmap_bench
