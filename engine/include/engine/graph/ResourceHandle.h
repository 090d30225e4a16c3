#pragma once

#include <cstdint>

namespace engine {

// A resource of one render graph: its index there and the graph's serial number, so a
// handle kept past its frame (or mixed up between graphs) is an error naming the pass that
// used it, never another graph's texture. Graph names are for Graphviz and messages only:
// resources are found by the handles their creators returned.
struct ResourceHandle {
    int index = -1;
    std::uint64_t graph = 0;  // RenderGraph serial; 0: returned by no graph
    bool valid() const { return index >= 0; }
    bool operator==(const ResourceHandle&) const = default;
};

} // namespace engine
