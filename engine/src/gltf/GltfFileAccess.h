#pragma once
// File access for glTF loading. tinygltf 2.7.0 opens any path a URI spells (`..`,
// absolute, `file:`, percent-encoded escapes, the current directory, directories): every
// read goes through here, and here only regular files inside the scene's folder are read.
#include <tiny_gltf.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace engine::gltf {

// Reads a whole regular file of at most maxBytes. On failure returns false and says why.
bool readRegularFile(const std::filesystem::path& path, std::uint64_t maxBytes,
                     std::vector<std::uint8_t>& contents, std::string& problem);

// Decodes a URI's percent escapes exactly as tinygltf does before it opens the file (it
// also turns '+' into a space), so we vet the very path tinygltf will open. Returns false
// for a malformed escape.
bool decodeUriLikeTinygltf(const std::string& uri, std::string& decoded);

// Checks a non-data URI of a buffer or image: relative, no scheme, no `..`, and naming a
// regular file of at most maxBytes whose real path (symlinks resolved) is inside `folder`
// (itself a real path). Returns the reason it is refused, or "" when it is fine.
std::string checkExternalUri(const std::string& uri, const std::filesystem::path& folder,
                             std::uint64_t maxBytes);

// What the tinygltf callbacks need; must outlive the tinygltf::TinyGLTF that uses them.
struct SceneFolderSandbox {
    std::filesystem::path folder;  // real path
    std::uint64_t maxFileBytes = 0;
};

// Callbacks that read only regular files inside the sandbox's folder, expand nothing
// (CVE-2022-3008 was shell expansion) and never write.
tinygltf::FsCallbacks makeSandboxedFsCallbacks(SceneFolderSandbox& sandbox);

} // namespace engine::gltf
