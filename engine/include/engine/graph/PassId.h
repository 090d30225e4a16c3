#pragma once

namespace engine {

// A pass of one frame's render graph, as RenderGraph::addPass returned it: its index in
// declaration order (RenderGraph::reports() and FrameResult::passes are in that order).
// Only meaningful for the graph that returned it.
struct PassId {
    int index = -1;
    bool valid() const { return index >= 0; }
    bool operator==(const PassId&) const = default;
};

} // namespace engine
