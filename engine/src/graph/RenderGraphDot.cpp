// graphviz(): the compiled graph as DOT, for docs and for seeing why a pass was culled.
#include "engine/graph/RenderGraph.h"

#include <sstream>

namespace engine {

namespace {
// A DOT double-quoted string; a newline becomes DOT's centered line break.
std::string label(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '\n') {
            out += "\\n";
            continue;
        }
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}
} // namespace

std::string RenderGraph::graphviz() const {
    std::ostringstream dot;
    dot << "digraph RenderGraph {\n  rankdir=LR;\n  node [fontname=\"Helvetica\"];\n";
    const bool haveReports = compiled_;  // before compile() show the declarations only
    auto passCulled = [&](int p) { return haveReports && reports_[p].culled; };

    for (int p = 0; p < static_cast<int>(passes_.size()); ++p) {
        dot << "  p" << p << " [shape=box, ";
        if (passCulled(p)) {
            dot << "style=dashed, color=grey, fontcolor=grey, label="
                << label(passes_[p].name + "\nculled: " + reports_[p].cullReason);
        } else {
            std::string text = passes_[p].name;
            if (haveReports && reports_[p].order >= 0) text += "\n#" + std::to_string(reports_[p].order);
            if (passes_[p].sideEffect) text += "\nside effect";
            dot << "label=" << label(text);
        }
        dot << "];\n";
    }
    for (int r = 0; r < static_cast<int>(resources_.size()); ++r) {
        const Resource& resource = resources_[r];
        std::string text = resource.name + "\n" + toString(resource.desc);
        if (compiled_ && resource.slot >= 0) text += "\nslot " + std::to_string(resource.slot);
        const bool unused = compiled_ && resource.firstUse < 0;
        dot << "  r" << r << " [shape=ellipse, label=" << label(text);
        if (resource.imported) dot << ", style=filled, fillcolor=lightsteelblue";
        if (resource.output) dot << ", peripheries=2";
        if (unused) dot << (resource.imported ? ", color=grey" : ", style=dashed, color=grey, fontcolor=grey");
        dot << "];\n";
    }
    const char* culledEdge = " [style=dashed, color=grey]";
    for (int p = 0; p < static_cast<int>(passes_.size()); ++p) {
        for (int r : passes_[p].writes)
            dot << "  p" << p << " -> r" << r << (passCulled(p) ? culledEdge : "") << ";\n";
        for (int r : passes_[p].reads)
            dot << "  r" << r << " -> p" << p << (passCulled(p) ? culledEdge : "") << ";\n";
    }
    dot << "}\n";
    return dot.str();
}

} // namespace engine
