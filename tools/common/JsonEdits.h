#pragma once
// Byte edits of a JSON text at the offsets scanJson found (JsonSpans.h): the in-place
// editors of scene files (SaveSettings.h, AddedLights.h) collect them and apply them at
// once, so every byte they do not edit stays as it was.
#include "JsonSpans.h"

#include <cstddef>
#include <string>
#include <vector>

namespace tools {

struct JsonEdit {
    std::size_t begin = 0, end = 0;  // [begin, end) of the original text is replaced by text
    std::string text;
};

// Applies `edits` to `text`. They must not overlap; several may insert at one offset (each
// inserted text is then a whole comma-led member or item, so their order does not matter).
std::string applyJsonEdits(std::string text, std::vector<JsonEdit> edits);

// Inserts the JSON texts `items` after the last item of `array` (an '[' span).
JsonEdit appendItems(const JsonSpan& array, const std::vector<std::string>& items);

// Inserts the member "key": valueText after the last member of `object` (a '{' span).
JsonEdit appendMember(const JsonSpan& object, const std::string& key, const std::string& valueText);

} // namespace tools
