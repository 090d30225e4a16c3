#pragma once
// Debian's assimp-testmodels: glTF files nobody here wrote, read by the loader and render
// tests. tools/install-deps.sh installs the package, so a missing folder is a broken setup:
// the tests that read it fail with this message instead of skipping, which would pass
// green while checking nothing.
#include <gtest/gtest.h>

#include <filesystem>

namespace engine::test {

inline const std::filesystem::path kAssimpGltf2Models = "/usr/share/assimp/models/glTF2";

inline ::testing::AssertionResult assimpTestModelsInstalled() {
    if (std::filesystem::is_directory(kAssimpGltf2Models)) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << kAssimpGltf2Models.string()
           << " is missing: install the Debian package assimp-testmodels (tools/install-deps.sh does)";
}

} // namespace engine::test
