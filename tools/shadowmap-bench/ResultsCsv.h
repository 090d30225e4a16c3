#pragma once
// results.csv: one row per scene x light x setting, columns exactly kResultsCsvHeader;
// a volume row (no map) leaves resolution, depth_format and filter empty;
// times in milliseconds, errors in percent (area_*: against the area truth, docs/metrics.md),
// shimmer and near_* in percent and empty when not measured (--shimmer, --near).
// Columns added later come last, so scripts reading the first ones keep working:
// light_size (the radius or angular diameter the light had; 0: none), filter_radius,
// filter_taps and normal_offset (empty where the sweep did not set them: the scene's value
// applied), soft_error, soft_error_noedge and penumbra_error (percent, against the soft
// truth; empty for a light without a size), texel_m_mean and texel_m_p95 (the on-screen
// size of the light's map texels in pixels, mean and 95th percentile over the evaluation
// set, docs/metrics.md; empty where no pixel has one), projection ("uniform" | "lispsm"),
// cascades ("auto" | 1..4) and stable ("true" | "false"): the directional lights' axes,
// empty where the sweep did not set them, and always on a spot or point light's rows;
// bleed_reduction (vsm and evsm rows with --bleed-reductions; empty elsewhere);
// frame_p99_ms and frame_max_ms (the frame time's tail beside frame_ms, the median: p99 and
// max over the same timed frames, every view's, nearest rank; under 100 frames p99 = max).
// Written here, read back by --merge (Shards.h).
#include "BenchRow.h"

#include <cstddef>
#include <string>
#include <vector>

namespace shadowmap_bench {

inline constexpr const char* kResultsCsvHeader =
    "scene,light,variant,resolution,depth_format,filter,shadow_ms,frame_ms,acne,leak,error,error_noedge,"
    "area_acne,area_leak,area_error,shimmer,near_error,near_error_noedge,"
    "light_size,filter_radius,filter_taps,normal_offset,soft_error,soft_error_noedge,penumbra_error,"
    "texel_m_mean,texel_m_p95,projection,cascades,stable,bleed_reduction,frame_p99_ms,frame_max_ms";
inline constexpr std::size_t kResultsCsvColumns = 33;

std::string resultsCsv(const std::vector<BenchRow>& rows);

} // namespace shadowmap_bench
