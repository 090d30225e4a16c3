#pragma once

#include <cstdint>

namespace engine {

// A resource of one render graph at one version: its index there, the graph's serial
// number, so a handle kept past its frame (or mixed up between graphs) is an error naming
// the pass that used it, never another graph's texture, and the version it names: a write
// returns a handle to the next version, and using an older one is an error (RenderGraph.h).
// Graph names are for Graphviz and messages only: resources are found by the handles their
// creators and writers returned.
struct ResourceHandle {
    int index = -1;
    std::uint64_t graph = 0;  // RenderGraph serial; 0: returned by no graph
    int version = 0;          // 0: as created or imported; each write adds one
    bool valid() const { return index >= 0; }
    bool operator==(const ResourceHandle&) const = default;
};

} // namespace engine
