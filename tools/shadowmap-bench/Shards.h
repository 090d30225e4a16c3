#pragma once
// Sweeps beyond one process: --shard K/N runs every N-th job (a job is one scene under one
// setting, numbered across scenes in sweep order, shard K taking jobs K-1, K-1+N, ...) and
// writes its rows with a manifest (shard.json); --merge reads the N folders back and
// writes what one run would have (rows in the single run's order). No scheduler of our
// own: GNU parallel or a Slurm job array starts the shards (docs/tuning.md, "Sharded sweeps").
#include "BenchRow.h"
#include "OptionValues.h"
#include "SummaryReport.h"
#include "Sweep.h"

#include <filesystem>
#include <string>
#include <vector>

namespace shadowmap_bench {

using tools::Shard;  // K of N (tools/common/OptionValues.h, which parses --shard)

// Drops from each scene the settings (jobs) other shards run.
void keepShardJobs(std::vector<BenchScene>& scenes, const Shard& shard);

// shard.json: which shard, where and how it was measured, and its rows per job (in order:
// SweepRows::jobRows), by which --merge deals the jobs back.
std::string shardManifest(const Shard& shard, const SweepDescription& sweep, const std::vector<int>& jobRows);

// results.csv back into rows; an InputError naming the file and line when it is not what
// resultsCsv writes.
std::vector<BenchRow> parseResultsCsv(const std::string& text, const std::string& file);

struct ShardResult {
    Shard shard;
    SweepDescription sweep;
    std::vector<BenchRow> rows;
    std::vector<int> jobRows;  // rows per job, adding up to rows.size()
};
// Reads DIR/shard.json and DIR/results.csv; InputError naming the file on anything missing,
// or when the manifest's jobs do not add up to the rows.
ShardResult readShard(const std::filesystem::path& dir);

// The shards' rows in the single run's order (jobs dealt round-robin back); the sweep's
// description from the first, its seconds the sum. InputError when the folders are not
// shards 1..N of one N, each once.
std::vector<BenchRow> mergeShards(const std::vector<ShardResult>& shards, SweepDescription& sweep);

} // namespace shadowmap_bench
