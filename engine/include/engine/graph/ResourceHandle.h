#pragma once

namespace engine {

// Index of a resource in its render graph; only meaningful for the graph that returned it.
struct ResourceHandle {
    int index = -1;
    bool valid() const { return index >= 0; }
    bool operator==(const ResourceHandle&) const = default;
};

} // namespace engine
