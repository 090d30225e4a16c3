#pragma once
// shadowmap-tune --shard K/N: lights are independent, so shard K searches the tuned lights
// K-1, K-1+N, ... (the others ride along at their current setting) and writes its choices as
// a partial result (JSON) instead of the scene; --merge reads the N partial results and
// writes the scene as one run would have (README, "Sharded sweeps").
#include "OptionValues.h"

#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <vector>

namespace shadowmap_tune {

// Whether shard `shard` searches the tuned light `tuned` (0-based, in tuned order).
inline bool inShard(const tools::Shard& shard, int tuned) { return tuned % shard.count == shard.index - 1; }

// The partial result: the scene it tuned, which shard, what it was tuned for (the record
// the tuned file keeps in asset.extras, e.g. the image size) and per glTF light index the
// extras.shadow to write (only lights this shard changed).
std::string partialResult(const std::string& scene, const tools::Shard& shard, const nlohmann::json& tunedFor,
                          const std::map<int, nlohmann::json>& shadows);

struct MergedResult {
    std::map<int, nlohmann::json> shadows;  // the union of the shards' edits
    nlohmann::json tunedFor;                 // every shard's, which must agree
};

// Reads the partial results, checks they are shards 1..N of one N for `scene`, each once,
// tuned for the same size, and returns the union of their edits. InputError naming the file
// otherwise.
MergedResult mergePartialResults(const std::vector<std::string>& files, const std::string& scene);

} // namespace shadowmap_tune
