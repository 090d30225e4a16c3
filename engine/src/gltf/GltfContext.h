#pragma once
// What every stage of the glTF loader shares: the file named in messages, the scene's
// folder (the only place URIs may point into), the limits, and where warnings go.
#include "engine/gltf/GltfLoader.h"
#include "engine/util/Error.h"
#include "engine/util/FormatNumber.h"

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace engine::gltf {

struct LoadContext {
    std::string file;               // as the caller named it: the first part of every message
    std::filesystem::path folder;   // real path of the scene's folder
    GltfLoadOptions options;
    std::vector<std::string>* warnings = nullptr;

    // Bad input: "file: object: reason". Never returns.
    [[noreturn]] void fail(const std::string& object, const std::string& reason) const {
        throwInputError(file, object, reason);
    }
    void warn(const std::string& object, const std::string& message) const {
        if (warnings) warnings->push_back(describeError(file, object, message));
    }
};

// "accessors[3]": how messages name a glTF object.
inline std::string indexed(std::string_view array, std::size_t index) {
    return std::string(array) + "[" + std::to_string(index) + "]";
}

// "nodes[3] 'Floor'": the index finds it in the file, the name finds it in an editor.
inline std::string withName(const std::string& object, const std::string& name) {
    return name.empty() ? object : object + " '" + name + "'";
}
inline std::string indexedNamed(std::string_view array, std::size_t index, const std::string& name) {
    return withName(indexed(array, index), name);
}

using engine::formatNumber;  // numbers in messages: engine/util/FormatNumber.h

} // namespace engine::gltf
