#pragma once
// ShaderLog: turns a driver's shader info log into a message a person can act on, by
// quoting the source line each diagnostic points at. Pure text, no GL: unit-testable.
//
// Recognised diagnostic prefixes (source string 0 only; we pass one string per stage):
//   Mesa:           0:LINE(COL): error: ...
//   NVIDIA:         0(LINE) : error C0000: ...
//   AMD, ANGLE:     ERROR: 0:LINE: ...
// Other log lines are kept verbatim.
#include <string>
#include <string_view>
#include <vector>

namespace engine::gl {

struct ShaderDiagnostic {
    int line = 0;        // 1-based source line; 0 if the log line names none
    std::string text;    // the log line as the driver wrote it
};

std::vector<ShaderDiagnostic> parseShaderLog(std::string_view log);

// The log, each diagnostic followed by the source line it names, numbered:
//   0:4(13): error: `undefinedThing' undeclared
//       4 |     fragColor = undefinedThing;
std::string annotateShaderLog(std::string_view log, std::string_view source);

} // namespace engine::gl
