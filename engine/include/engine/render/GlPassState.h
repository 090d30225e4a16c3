#pragma once
// Applies a pass's declared state (graph/PassState.h) to the current GL context: every
// field, every time, plus what no pass of ours uses (blending, scissor), switched off.
#include "engine/graph/PassState.h"

namespace engine {

void applyPassState(const PassState& state);

} // namespace engine
