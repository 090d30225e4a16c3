#pragma once
// The textures a pass draws into, and the clears it starts from, declared with the pass
// (PassBuilder::setTargets) and bound by the executor after the pass's state and before it
// runs (ExecuteOptions::bindTargets; GlPassTargets.h in practice). A pass that declares none
// runs with the default framebuffer bound, so no pass draws into what the one before it left
// bound. Every attachment must be a resource the pass writes. Plain data: no GL here.
#include "engine/graph/ResourceHandle.h"

#include <array>
#include <optional>
#include <vector>

namespace engine {

struct ColorTarget {
    ResourceHandle resource;
    int layer = -1;  // an array layer or cube face; -1: a texture without layers
    std::optional<std::array<float, 4>> clear;  // RGBA, converted like the pass's writes
};

struct DepthTarget {
    ResourceHandle resource;  // invalid: no depth attachment
    int layer = -1;
    std::optional<float> clear;
};

struct PassTargets {
    std::vector<ColorTarget> colors;  // fragment output i writes colors[i]
    DepthTarget depth;
    bool empty() const { return colors.empty() && !depth.resource.valid(); }

    // A depth-only target (a shadow map layer).
    static PassTargets depthOnly(ResourceHandle resource, int layer = -1, std::optional<float> clear = std::nullopt) {
        PassTargets targets;
        targets.depth = DepthTarget{resource, layer, clear};
        return targets;
    }
};

} // namespace engine
