#pragma once
// Where each value of a JSON text lies, byte by byte, so a file can be edited in place:
// SaveSettings (engine-view, shadowmap-tune) replaces the lights' extras.shadow and leaves every other byte as it was
// (nlohmann::json, like other JSON libraries, re-formats a whole document when it writes
// it). Only the structure is recorded: object members (keys decoded), array items and each
// value's [begin, end) offsets; strings and numbers are skipped, not decoded.
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tools {

struct JsonSpan {
    std::size_t begin = 0, end = 0;  // the value's text is [begin, end)
    char kind = 0;                   // '{', '[', '"', or 'v' (number, true, false, null)
    std::vector<std::pair<std::string, JsonSpan>> members;  // objects, in text order
    std::vector<JsonSpan> items;                            // arrays

    const JsonSpan* member(const std::string& key) const;  // the last with that key, or null
};

// Throws std::invalid_argument naming the byte offset on malformed text (callers parse with
// nlohmann first, so that is a bug).
JsonSpan scanJson(std::string_view text);

} // namespace tools
