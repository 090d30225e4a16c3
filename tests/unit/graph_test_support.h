#pragma once
// What the render graph's tests share.
#include "engine/graph/RenderGraph.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace engine::test {

// Runs `action`, which must throw a GraphError whose message names every piece in `parts`.
template <class F>
void expectGraphError(F&& action, const std::vector<std::string>& parts) {
    try {
        action();
        ADD_FAILURE() << "expected a GraphError";
    } catch (const GraphError& error) {
        const std::string message = error.what();
        for (const std::string& part : parts)
            EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' missing from: " << message;
    }
}

} // namespace engine::test
