#pragma once
// A scene file's asset.extras members, edited in place like the lights' settings
// (SaveSettings.h): the tools record there what a file's settings were made for, e.g.
// shadowmap-tune's "shadowmap_tune": {"width": 1280, "height": 720, ...}, the image size its
// choice was measured at, which engine-render compares with the size it renders.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace tools {

// The JSON text with asset.extras[key] = value for each entry (asset.extras created when
// missing, an existing member replaced), every other byte kept. Throws InputError naming
// `fileName` when asset or asset.extras is not an object, and std::logic_error if the result
// does not parse to the original document with the edits (our bug).
std::string setAssetExtras(const std::string& json, const std::map<std::string, nlohmann::json>& extras,
                           const std::string& fileName);

// What shadowmap-tune recorded in a loaded document: the image size it measured at.
struct TunedSize {
    int width = 0, height = 0;
};
inline constexpr const char* kTunedForKey = "shadowmap_tune";
// The record as written ({"width": W, "height": H}) and read back from a document.
nlohmann::json tunedSizeRecord(const TunedSize& size);
std::optional<TunedSize> tunedSize(const nlohmann::json& document);
// The same read from a scene file (.gltf or .glb: only its JSON is read); nullopt when the
// file has no such record or cannot be read (the loader has its own, clear errors).
std::optional<TunedSize> readTunedSize(const std::filesystem::path& scene);

// Whether a picture of `width` x `height` is far from the size the settings were tuned at:
// more than twice or less than half its pixels, where a map's texels on screen grow or shrink
// by more than a factor √2 on each axis and the tuner's ranking may no longer hold.
bool farFromTunedSize(const TunedSize& tuned, int width, int height);

} // namespace tools
