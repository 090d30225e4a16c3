#include "JsonEdits.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace tools {

std::string applyJsonEdits(std::string text, std::vector<JsonEdit> edits) {
    // From the back, so earlier offsets stay valid.
    std::stable_sort(edits.begin(), edits.end(), [](const JsonEdit& a, const JsonEdit& b) { return a.begin > b.begin; });
    for (const JsonEdit& edit : edits) text.replace(edit.begin, edit.end - edit.begin, edit.text);
    return text;
}

namespace {

// An insertion just inside the opening bracket of an empty container, else right after its
// last entry (ending at `lastEnd`), comma-led.
JsonEdit insertAtEnd(const JsonSpan& container, bool empty, std::size_t lastEnd, const std::string& joined) {
    if (empty) return {container.begin + 1, container.begin + 1, joined};
    return {lastEnd, lastEnd, "," + joined};
}

} // namespace

JsonEdit appendItems(const JsonSpan& array, const std::vector<std::string>& items) {
    std::string joined;
    for (const std::string& item : items) joined += (joined.empty() ? "" : ",") + item;
    return insertAtEnd(array, array.items.empty(), array.items.empty() ? 0 : array.items.back().end, joined);
}

JsonEdit appendMember(const JsonSpan& object, const std::string& key, const std::string& valueText) {
    return insertAtEnd(object, object.members.empty(), object.members.empty() ? 0 : object.members.back().second.end,
                       nlohmann::json(key).dump() + ":" + valueText);
}

} // namespace tools
