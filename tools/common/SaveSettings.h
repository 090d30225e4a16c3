#pragma once
// The one editor of a scene file's per-light settings: engine-view's --save-settings and
// shadowmap-tune --out write the scene back with each light's extras.shadow replaced by the
// settings chosen (by eye or by measurement), so engine-render and the bench use them.
//
// Every other byte of the file stays as loaded: the JSON is edited in place (JsonSpans.h),
// only the "shadow" member of each edited light's "extras" is replaced (or inserted, with
// an "extras" object when the light had none), as compact JSON. A .glb keeps its binary
// chunk byte for byte (the JSON chunk is re-padded with spaces and the lengths updated);
// a .gltf is written as .gltf, a .glb as .glb.
//
// Buffers and images keep their URIs. A relative URI resolves from the file that holds it,
// and the loader reads only from the scene's folder, so a scene that refers to external
// files (e.g. showcase.bin) must be saved in the same folder as the scene it was loaded
// from; anything else is an InputError saying so (data: URIs and .glb files go anywhere).
// The file is written through a temporary file and a rename (engine::writeFileAtomically).
#include "AddedLights.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace tools {

// Throws the InputError saveSceneSettings would throw before writing: `out` has the other
// container, is a directory, its folder is missing or not writable, or the scene's external
// files would not resolve from it. engine-view calls it at start, so a bad --save-settings
// is one clear error then, not a surprise after an hour of tuning (shadowmap-tune likewise,
// before its first render).
void checkSaveTarget(const std::filesystem::path& scene, const std::filesystem::path& out);

// `shadows`: glTF light index (KHR_lights_punctual.lights[i]) -> its new extras.shadow.
// `added`: lights the tool added to the scene, written into the file too (AddedLights.h).
void saveSceneSettings(const std::filesystem::path& scene, const std::filesystem::path& out,
                       const std::map<int, nlohmann::json>& shadows, const std::vector<AddedLight>& added = {});

// The JSON text with those edits, every other byte kept. Throws InputError naming
// `fileName` when a light index does not exist, and std::logic_error if the result does
// not parse to the original document with the edits (our bug).
std::string replaceLightShadows(const std::string& json, const std::map<int, nlohmann::json>& shadows,
                                const std::string& fileName);

} // namespace tools
