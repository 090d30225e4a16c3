#pragma once
// What the engine-render tests share: running the tool quietly, reading a shadow mask and
// the stats it wrote, and counting pixels whose shadow state differs between two masks.
#include "engine/util/OutputFile.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/wait.h>

namespace engine_render_test {

struct CommandResult {
    int exitCode = -1;
    std::string output;  // stdout + stderr
};

// engine-render ARGUMENTS as a user runs it, started in `folder` if one is given: its exit
// status and everything it printed.
inline CommandResult runEngineRender(const std::string& arguments, const std::filesystem::path& folder = {}) {
    const std::string command = (folder.empty() ? std::string() : "cd '" + folder.string() + "' && ") +
                                std::string(ENGINE_RENDER_BIN) + " " + arguments + " 2>&1";
    CommandResult result;
    FILE* pipe = popen(command.c_str(), "r");
    std::array<char, 4096> buffer{};
    while (pipe && fgets(buffer.data(), buffer.size(), pipe)) result.output += buffer.data();
    const int status = pipe ? pclose(pipe) : -1;
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

// Runs a shell command with its standard output discarded and its error output written to
// `errorLog` (discarded too when empty); its exit status, -1 if it did not exit.
inline int runQuietly(const std::string& command, const std::filesystem::path& errorLog = {}) {
    const std::string errors = errorLog.empty() ? std::string("&1") : " '" + errorLog.string() + "'";
    const int status = std::system((command + " > /dev/null 2>" + errors).c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// engine-render with the repository's config on `scene` at width x height plus `flags`;
// returns the stats it wrote (null JSON if none). Fails the test if the tool fails.
inline nlohmann::json renderWithStats(const std::filesystem::path& scene, const std::filesystem::path& outputStem,
                                      int width, int height, const std::string& flags) {
    const std::filesystem::path stats = outputStem.string() + ".json";
    const std::string command = std::string(ENGINE_RENDER_BIN) + " --config " + CONTENT_DIR + "/engine.json --scene '" +
                                scene.string() + "' --out '" + outputStem.string() + ".png' --width " +
                                std::to_string(width) + " --height " + std::to_string(height) + " --stats '" +
                                stats.string() + "' " + flags;
    // The tool's messages go to a log beside the stats, quoted when it fails.
    const std::filesystem::path log = outputStem.string() + ".log";
    const int status = runQuietly(command, log);
    if (status != 0) {
        std::ifstream messages(log);
        const std::string text((std::istreambuf_iterator<char>(messages)), std::istreambuf_iterator<char>());
        ADD_FAILURE() << command << "\nexited with " << status << ":\n" << text;
    }
    std::ifstream in(stats);
    return in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
}

inline std::vector<std::uint8_t> readMask(const std::filesystem::path& file) {
    int width = 0, height = 0;
    return engine::readPng(file, 1, width, height);
}

// The entry of `list` (the stats' "lights" or "shadow_maps") for light `name`.
inline const nlohmann::json* lightEntry(const nlohmann::json& list, const std::string& name) {
    for (const nlohmann::json& entry : list)
        if (entry.value("light", "") == name) return &entry;
    ADD_FAILURE() << "no light '" << name << "' in " << list.dump();
    return nullptr;
}

// Pixels whose shadow state (lit above 127) differs between two masks.
inline int differingPixels(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    int count = 0;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) count += (a[i] > 127) != (b[i] > 127);
    return count;
}

// content/scenes/NAME.gltf's JSON, with its NAME.bin copied into `folder`, for a test to edit
// and write there as engine-render's scene.
inline nlohmann::json copyContentScene(const std::filesystem::path& folder, const std::string& name) {
    std::filesystem::copy_file(std::filesystem::path(CONTENT_DIR) / "scenes" / (name + ".bin"),
                               folder / (name + ".bin"), std::filesystem::copy_options::overwrite_existing);
    std::ifstream in(std::filesystem::path(CONTENT_DIR) / "scenes" / (name + ".gltf"));
    return nlohmann::json::parse(in);
}

// The KHR_lights_punctual light called `name` in a scene's JSON; throws when there is none.
inline nlohmann::json& lightNamed(nlohmann::json& scene, const std::string& name) {
    for (auto& light : scene["extensions"]["KHR_lights_punctual"]["lights"])
        if (light["name"] == name) return light;
    throw std::runtime_error("no light " + name);
}

} // namespace engine_render_test
