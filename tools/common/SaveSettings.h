#pragma once
// The one editor of a scene file's per-light settings: engine-view's --save-settings and
// shadowmap-tune --out write the scene back with each light's extras.shadow replaced by the
// settings chosen (by eye or by measurement), so engine-render and the bench use them.
//
// The output's name picks its container: .glb writes a .glb, .gltf a .gltf, any other name
// the scene's own. In the same container every other byte of the file stays as loaded: the
// JSON is edited in place (JsonSpans.h), only the "shadow" member of each edited light's
// "extras" is replaced (or inserted, with an "extras" object when the light had none), as
// compact JSON; a .glb keeps its binary chunk byte for byte (the JSON chunk is re-padded
// with spaces and the lengths updated). Across containers the layout changes anyway, so the
// edited JSON is rewritten with nlohmann (SceneContainers.h; member order kept): a .gltf
// saved as .glb has every buffer and image embedded in the BIN chunk; a .glb saved as
// .gltf has its BIN chunk written beside it as <output's stem>.bin.
//
// Files the scene refers to by relative URI (buffers, images) resolve from the saved file's
// folder, so saved elsewhere they are copied there at the same relative path (sub-folders
// created), after the loader's own URI checks (engine/gltf/GltfUris.h: a URI it would
// refuse is an InputError here too). A destination that already holds the same bytes is
// left alone; one that holds other bytes is never replaced (InputError naming it), nor is a
// destination written whose folder cannot take it. Everything is checked before anything is
// written; the files beside the scene are written first and the scene last, each through a
// temporary file and a rename (engine::writeFileAtomically), and a save that fails part way
// removes the files and folders it created.
#include "AddedLights.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace tools {

// Throws the InputError saveSceneSettings would throw before writing: `out` is a directory,
// its folder is missing or not writable, a file the scene refers to cannot be copied or
// embedded, or a file beside `out` is in the way. engine-view calls it at start, so a bad
// --save-settings is one clear error then, not a surprise after an hour of tuning
// (shadowmap-tune likewise, before its first render).
void checkSaveTarget(const std::filesystem::path& scene, const std::filesystem::path& out);

// `shadows`: glTF light index (KHR_lights_punctual.lights[i]) -> its new extras.shadow.
// `added`: lights the tool added to the scene, written into the file too (AddedLights.h).
// `assetExtras`: members set in asset.extras (AssetExtras.h), e.g. what the settings were tuned for.
void saveSceneSettings(const std::filesystem::path& scene, const std::filesystem::path& out,
                       const std::map<int, nlohmann::json>& shadows, const std::vector<AddedLight>& added = {},
                       const std::map<std::string, nlohmann::json>& assetExtras = {});

// The JSON text with those edits, every other byte kept. Throws InputError naming
// `fileName` when a light index does not exist, and std::logic_error if the result does
// not parse to the original document with the edits (our bug).
std::string replaceLightShadows(const std::string& json, const std::map<int, nlohmann::json>& shadows,
                                const std::string& fileName);

} // namespace tools
