#include "engine/gl/ShaderLog.h"

#include <cstdio>
#include <regex>

namespace engine::gl {

namespace {

std::vector<std::string_view> splitLines(std::string_view text) {
    std::vector<std::string_view> lines;
    while (!text.empty()) {
        const auto end = text.find('\n');
        lines.push_back(text.substr(0, end));
        if (end == std::string_view::npos) break;
        text.remove_prefix(end + 1);
    }
    return lines;
}

int lineNumberOf(const std::string& logLine) {
    // One alternative per driver family; the line number is whichever group matched.
    static const std::regex pattern(R"(^\s*(?:\d+:(\d+)\(\d+\))"       // Mesa    0:LINE(COL)
                                    R"(|\d+\((\d+)\))"                   // NVIDIA  0(LINE)
                                    R"(|(?:ERROR|WARNING): \d+:(\d+)))");  // AMD     ERROR: 0:LINE
    std::smatch match;
    if (!std::regex_search(logLine, match, pattern)) return 0;
    for (std::size_t group = 1; group < match.size(); ++group)
        if (match[group].matched) return std::stoi(match[group].str());
    return 0;
}

} // namespace

std::vector<ShaderDiagnostic> parseShaderLog(std::string_view log) {
    std::vector<ShaderDiagnostic> diagnostics;
    for (const std::string_view line : splitLines(log)) {
        if (line.find_first_not_of(" \t\r") == std::string_view::npos) continue;
        std::string text(line);
        diagnostics.push_back({lineNumberOf(text), std::move(text)});
    }
    return diagnostics;
}

std::string annotateShaderLog(std::string_view log, std::string_view source) {
    const std::vector<std::string_view> sourceLines = splitLines(source);
    std::string report;
    for (const ShaderDiagnostic& diagnostic : parseShaderLog(log)) {
        report += diagnostic.text + '\n';
        if (diagnostic.line < 1 || diagnostic.line > static_cast<int>(sourceLines.size()))
            continue;
        char number[16];
        std::snprintf(number, sizeof number, "%7d | ", diagnostic.line);
        report += number;
        report += sourceLines[diagnostic.line - 1];
        report += '\n';
    }
    return report;
}

} // namespace engine::gl
