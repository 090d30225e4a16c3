#pragma once
// time_vs_error.gp: a self-contained gnuplot script (the measured points are inline data
// blocks) drawing, per scene, one panel of shadow time (x) against error (y): one colour
// per light, one point shape per variant (volume, one point per light: a large pentagon,
// "volume (no map)" in the legend), each light's Pareto front as a line whose points
// are labelled by setting (only steps of >= 5 % in error, so labels stay legible). Run it in its folder; `gnuplot -e "output='X.png'"` renames the
// picture (default time_vs_error.png).
#include "BenchRow.h"

#include <string>
#include <vector>

namespace shadowmap_bench {

std::string timeErrorPlotScript(const std::vector<BenchRow>& rows);

} // namespace shadowmap_bench
