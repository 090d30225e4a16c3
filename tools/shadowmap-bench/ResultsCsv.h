#pragma once
// results.csv: one row per scene x light x setting, columns exactly kResultsCsvHeader;
// times in milliseconds, errors in percent (area_*: against the area truth, docs/metrics.md),
// shimmer and near_* in percent and empty when not measured (--shimmer, --near).
// Written here, read back by --merge (Shards.h).
#include "BenchRow.h"

#include <cstddef>
#include <string>
#include <vector>

namespace shadowmap_bench {

inline constexpr const char* kResultsCsvHeader =
    "scene,light,variant,resolution,depth_format,filter,shadow_ms,frame_ms,acne,leak,error,error_noedge,"
    "area_acne,area_leak,area_error,shimmer,near_error,near_error_noedge";
inline constexpr std::size_t kResultsCsvColumns = 18;

std::string resultsCsv(const std::vector<BenchRow>& rows);

} // namespace shadowmap_bench
