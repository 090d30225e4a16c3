#pragma once
// shadowmap-stress outputs, all in the --out folder:
//   stress.csv            one row per rendered case (Row, errors in percent)
//   <sweep>.png           error against the swept value, one panel per light kind, one
//                         line per variant/format (gnuplot; plots/<sweep>.gp and .dat are
//                         kept so a plot can be remade or restyled)
//   summary.md            the machine, the pass/fail table of the bounds (Sweeps.h), the
//                         failures, and one table per sweep
#include "Sweeps.h"

#include <filesystem>
#include <string>
#include <vector>

namespace stress {

struct RunInfo {
    std::string commandLine;
    std::string machine;      // nproc, CPU model
    std::string glRenderer;   // GL_RENDERER / GL_VERSION
    int width = 0, height = 0, resolution = 0;
    double seconds = 0.0;     // the whole run
    bool quick = false;
};

void writeCsv(const std::filesystem::path& path, const std::vector<Row>& rows);

// Writes <dir>/<sweep>.png per sweep with rows. Returns false (and says why in `warning`)
// when gnuplot is missing or fails; the CSV and summary do not depend on it.
bool writePlots(const std::filesystem::path& dir, const std::vector<Sweep>& sweeps,
                const std::vector<Row>& rows, std::string& warning);

void writeSummary(const std::filesystem::path& path, const RunInfo& info, const std::vector<Sweep>& sweeps,
                  const std::vector<Row>& rows, const std::vector<BoundResult>& bounds, bool plotsWritten);

// "nproc N, <CPU model>" from the running machine.
std::string describeMachine();

} // namespace stress
