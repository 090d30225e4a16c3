#pragma once
// results.csv: one row per scene x light x setting, columns exactly
//   scene,light,variant,resolution,depth_format,filter,shadow_ms,frame_ms,acne,leak,error,error_noedge
// times in milliseconds, errors in percent.
#include "BenchRow.h"

#include <string>
#include <vector>

namespace shadowmap_bench {

std::string resultsCsv(const std::vector<BenchRow>& rows);

} // namespace shadowmap_bench
