#include "SaveSettings.h"

#include "AssetExtras.h"
#include "JsonEdits.h"
#include "SceneContainers.h"

#include "engine/gltf/GltfLoader.h"
#include "engine/gltf/GltfUris.h"
#include "engine/util/Error.h"
#include "engine/util/InputFile.h"
#include "engine/util/OutputFile.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace fs = std::filesystem;

namespace tools {

namespace {

void writeU32(std::string& bytes, std::size_t at, std::uint32_t value) {
    for (int i = 0; i < 4; ++i) bytes[at + i] = static_cast<char>((value >> (8 * i)) & 0xFF);
}

} // namespace

std::string replaceLightShadows(const std::string& json, const std::map<int, nlohmann::json>& shadows,
                                const std::string& fileName) {
    nlohmann::json expected = nlohmann::json::parse(json);
    const JsonSpan root = scanJson(json);
    const JsonSpan* extensions = root.member("extensions");
    const JsonSpan* punctual = extensions ? extensions->member("KHR_lights_punctual") : nullptr;
    const JsonSpan* lights = punctual ? punctual->member("lights") : nullptr;
    std::vector<JsonEdit> edits;
    for (const auto& [index, shadow] : shadows) {
        if (!lights || index < 0 || index >= static_cast<int>(lights->items.size()) || lights->items[index].kind != '{')
            engine::throwInputError(fileName, "KHR_lights_punctual.lights[" + std::to_string(index) + "]",
                                    "no such light object to save settings into");
        const JsonSpan& light = lights->items[index];
        const std::string value = shadow.dump();
        const JsonSpan* extras = light.member("extras");
        if (extras && extras->kind != '{')
            engine::throwInputError(fileName, "KHR_lights_punctual.lights[" + std::to_string(index) + "].extras",
                                    "is not an object");
        if (!extras) edits.push_back(appendMember(light, "extras", "{\"shadow\":" + value + "}"));
        else if (const JsonSpan* old = extras->member("shadow")) edits.push_back({old->begin, old->end, value});
        else edits.push_back(appendMember(*extras, "shadow", value));
        expected["extensions"]["KHR_lights_punctual"]["lights"][index]["extras"]["shadow"] = shadow;
    }
    const std::string out = applyJsonEdits(json, std::move(edits));
    if (nlohmann::json::parse(out) != expected)
        throw std::logic_error("saving settings into " + fileName + " changed more than the lights' extras.shadow");
    return out;
}

namespace {

std::string lowerExtension(const fs::path& path) {
    std::string text = path.extension().string();
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

// The scene as saveSceneSettings edits it: its bytes, container, JSON text and BIN chunk.
struct SceneFile {
    std::string bytes;
    bool glb = false;
    std::string json;
    std::string bin;             // .glb: the BIN chunk's payload (empty when none)
    std::size_t jsonLength = 0;  // .glb: the JSON chunk's length
};

SceneFile readScene(const fs::path& scene) {
    SceneFile file;
    file.bytes = engine::readWholeFile(scene, "the scene");
    file.glb = file.bytes.size() >= 20 && file.bytes.compare(0, 4, "glTF") == 0;
    if (file.glb) {
        GlbChunks chunks = splitGlb(file.bytes, scene.string());
        file.jsonLength = chunks.json.size();
        file.json = std::move(chunks.json);
        file.bin = std::move(chunks.bin);
    } else {
        file.json = file.bytes;
    }
    return file;
}

// A file written beside the saved scene: a copy of one the scene refers to, or the BIN chunk
// of a .glb saved as .gltf.
struct SideFile {
    fs::path destination;
    std::string what;    // for messages, e.g. "buffers[0] (uri 'showcase.bin')"
    fs::path source;     // copied from here when `bytes` is empty
    std::string bytes;
    bool alreadyThere = false;  // an identical file is at the destination: nothing to write
};

// What saving `scene` to `out` writes, every check done: the output's container and the
// files beside it.
struct SavePlan {
    bool glb = false;  // the output's container
    fs::path sceneFolder;
    std::string binUri;  // .glb saved as .gltf: the uri of the BIN chunk's file
    std::vector<SideFile> sideFiles;
};

std::string inQuotes(const std::string& text) { return "'" + text + "'"; }

// The folder a file is in, "." for a bare name (so paths built from it stay as the user
// spelled them in messages).
fs::path folderOf(const fs::path& path) { return path.parent_path().empty() ? "." : path.parent_path(); }

bool sameFile(const fs::path& a, const fs::path& b) {
    std::error_code error;
    return fs::equivalent(a, b, error);
}

bool isInside(const fs::path& path, const fs::path& folder) {
    auto p = path.begin();
    for (auto f = folder.begin(); f != folder.end(); ++f, ++p)
        if (p == path.end() || *p != *f) return false;
    return p != path.end();
}

// Whether the file at side.destination already holds what the save would write there.
bool identicalAlready(const SideFile& side) {
    std::error_code error;
    if (side.bytes.empty() && sameFile(side.source, side.destination)) return true;
    const std::uintmax_t size = side.bytes.empty() ? fs::file_size(side.source, error) : side.bytes.size();
    if (error || fs::file_size(side.destination, error) != size || error) return false;
    const std::string there = engine::readWholeFile(side.destination, "a file in the way");
    return there == (side.bytes.empty() ? engine::readWholeFile(side.source, "a file the scene refers to") : side.bytes);
}

// Refuses a destination that cannot take `side`, or marks it alreadyThere when an identical
// file is in place. Never replaces a file with other content: the user may have put it there.
void checkDestination(SideFile& side, const fs::path& out, const fs::path& realOutFolder) {
    const std::string file = side.destination.string();
    std::error_code error;
    if (sameFile(side.destination, out) ||
        fs::absolute(side.destination).lexically_normal() == fs::absolute(out).lexically_normal())
        engine::throwInputError(file, side.what, "is the saved scene's own file: save the scene under another name");
    if (fs::exists(fs::symlink_status(side.destination, error))) {
        if (!fs::is_regular_file(side.destination, error))
            engine::throwInputError(file, side.what, "something other than a file is already there: not replaced");
        if (identicalAlready(side)) {
            side.alreadyThere = true;
            return;
        }
        engine::throwInputError(file, side.what, "a different file is already there: not replaced (move it away "
                                                 "or save elsewhere)");
    }
    // The nearest folder that exists must take the new folders (if any) and the file.
    fs::path folder = side.destination.parent_path().empty() ? fs::path(".") : side.destination.parent_path();
    while (!fs::exists(fs::symlink_status(folder, error)) && folder.has_parent_path() && folder != folder.parent_path())
        folder = folder.parent_path();
    if (!fs::is_directory(folder, error))
        engine::throwInputError(file, side.what, folder.string() + " is not a folder, so the file cannot go there");
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        engine::throwInputError(file, side.what, "its folder " + folder.string() + " is not writable: " +
                                                     std::strerror(errno));
    // A symlinked sub-folder could lead elsewhere: the loader reads only inside the folder.
    const fs::path resolved = fs::weakly_canonical(fs::absolute(side.destination), error);
    if (error) engine::throwInputError(file, side.what, "cannot resolve the path: " + error.message());
    if (!isInside(resolved, realOutFolder))
        engine::throwInputError(file, side.what, "resolves to " + resolved.string() + ", outside the saved scene's "
                                                 "folder " + realOutFolder.string() + ", where the loader would not "
                                                 "read it");
}

// Everything that would make saving `file` (loaded from `scene`) to `out` fail, short of
// the writes themselves; `out`'s name picks the container (.glb or .gltf; another name
// keeps the scene's).
SavePlan planSave(const fs::path& scene, const SceneFile& file, const fs::path& out) {
    SavePlan plan;
    const std::string extension = lowerExtension(out);
    plan.glb = extension == ".glb" ? true : extension == ".gltf" ? false : file.glb;
    engine::checkOutputPath(out);

    const nlohmann::json document = nlohmann::json::parse(file.json, nullptr, false);
    if (document.is_discarded()) engine::throwInputError(scene.string(), "", "the JSON no longer parses");
    std::error_code error;
    plan.sceneFolder = folderOf(scene);
    const fs::path realOutFolder = fs::weakly_canonical(fs::absolute(folderOf(out)), error);
    const bool sameFolder = fs::weakly_canonical(fs::absolute(plan.sceneFolder), error) == realOutFolder;
    const std::uint64_t maxBytes = engine::GltfLoadOptions{}.maxFileBytes;

    // Files by relative URI: embedded into a .glb made from a .gltf, else copied to the same
    // relative place beside the output (nothing to copy in the scene's own folder).
    const bool embed = plan.glb && !file.glb;
    for (const char* list : {"buffers", "images"}) {
        if (!document.contains(list) || !document[list].is_array()) continue;
        for (std::size_t i = 0; i < document[list].size(); ++i) {
            const nlohmann::json& entry = document[list][i];
            if (!entry.is_object() || !entry.contains("uri") || !entry["uri"].is_string()) continue;
            const std::string uri = entry["uri"];
            if (engine::isGltfDataUri(uri) || (!embed && sameFolder)) continue;
            const std::string object = std::string(list) + "[" + std::to_string(i) + "]";
            if (const std::string problem = engine::gltfExternalUriProblem(uri, plan.sceneFolder, maxBytes);
                !problem.empty())
                engine::throwInputError(scene.string(), object, problem + (embed ? ": cannot embed it in " :
                                                                                   ": cannot copy it beside ") +
                                                                    out.string());
            if (embed) continue;
            std::string relative;
            engine::decodeGltfUri(uri, relative);  // cannot fail: gltfExternalUriProblem decoded it
            SideFile side{folderOf(out) / relative, object + " (uri " + inQuotes(uri) + ")", plan.sceneFolder / relative, {}};
            const bool duplicate = std::any_of(plan.sideFiles.begin(), plan.sideFiles.end(),
                                               [&](const SideFile& other) {
                                                   return other.destination.lexically_normal() ==
                                                          side.destination.lexically_normal();
                                               });
            if (!duplicate) plan.sideFiles.push_back(std::move(side));
        }
    }

    // A .glb saved as .gltf: the BIN chunk goes to a .bin file beside it rather than a data
    // URI: the .gltf stays small enough to read and edit, and the bytes are not inflated by a
    // third (base64).
    if (file.glb && !plan.glb) {
        if (std::optional<std::string> stored = glbStoredBuffer(document, file.bin, scene.string())) {
            const std::string name = out.stem().string() + ".bin";
            plan.binUri = encodeUriPath(name);
            SideFile side{folderOf(out) / name, "buffers[0] (the GLB's BIN chunk, as uri " + inQuotes(plan.binUri) + ")",
                          {}, std::move(*stored)};
            if (side.bytes.empty())  // the copy code takes empty bytes for "copy the source"
                engine::throwInputError(scene.string(), "buffers[0]", "byteLength is 0 (glTF requires at least 1)");
            for (const SideFile& other : plan.sideFiles)
                if (other.destination == side.destination)
                    engine::throwInputError(side.destination.string(), side.what,
                                            "the scene's " + other.what + " is copied there too: save under another name");
            plan.sideFiles.push_back(std::move(side));
        }
    }
    for (SideFile& side : plan.sideFiles) checkDestination(side, out, realOutFolder);
    return plan;
}

// Removes what a save created when it fails part way, so a failed save leaves no half of a
// scene behind (files that were there before are never touched: identical ones are skipped).
class CreatedPaths {
public:
    CreatedPaths() = default;
    CreatedPaths(const CreatedPaths&) = delete;
    CreatedPaths& operator=(const CreatedPaths&) = delete;
    ~CreatedPaths() {
        if (kept_) return;
        std::error_code ignored;
        for (auto path = paths_.rbegin(); path != paths_.rend(); ++path) fs::remove(*path, ignored);
    }
    // Creates the missing folders above `file`, remembering each.
    void createFoldersFor(const fs::path& file) {
        std::vector<fs::path> missing;
        std::error_code error;
        for (fs::path folder = file.parent_path(); !folder.empty() && !fs::exists(folder, error);
             folder = folder.parent_path())
            missing.push_back(folder);
        for (auto folder = missing.rbegin(); folder != missing.rend(); ++folder) {
            if (!fs::create_directory(*folder, error) && error)
                engine::throwInputError(file.string(), "", "cannot create its folder " + folder->string() + ": " +
                                                               error.message());
            paths_.push_back(*folder);
        }
    }
    void add(const fs::path& file) { paths_.push_back(file); }
    void keep() { kept_ = true; }

private:
    std::vector<fs::path> paths_;
    bool kept_ = false;
};

} // namespace

void checkSaveTarget(const fs::path& scene, const fs::path& out) {
    planSave(scene, readScene(scene), out);
}

void saveSceneSettings(const fs::path& scene, const fs::path& out, const std::map<int, nlohmann::json>& shadows,
                       const std::vector<AddedLight>& added,
                       const std::map<std::string, nlohmann::json>& assetExtras) {
    const SceneFile file = readScene(scene);
    const SavePlan plan = planSave(scene, file, out);
    const std::string edited = setAssetExtras(
        addLights(replaceLightShadows(file.json, shadows, scene.string()), added, scene.string()), assetExtras,
        scene.string());

    std::string result;
    if (plan.glb == file.glb && !file.glb) {
        result = edited;
    } else if (plan.glb == file.glb) {
        std::string json = edited;
        json.append((4 - json.size() % 4) % 4, ' ');  // GLB chunks are 4-byte aligned, JSON padded with spaces
        result = file.bytes.substr(0, 12);
        result.append(8, '\0');
        writeU32(result, 12, static_cast<std::uint32_t>(json.size()));
        result.replace(16, 4, "JSON");
        result += json;
        result += file.bytes.substr(20 + file.jsonLength);  // the BIN chunk (and any other) as it was
        writeU32(result, 8, static_cast<std::uint32_t>(result.size()));
    } else if (plan.glb) {
        const ExternalFileReader read = [&](const std::string&, const std::string& uri) {
            std::string relative;
            engine::decodeGltfUri(uri, relative);  // vetted by planSave
            return engine::readWholeFile(plan.sceneFolder / relative, "a file the scene refers to");
        };
        result = gltfToGlb(nlohmann::ordered_json::parse(edited), read, scene.string());
    } else {
        result = glbToGltf(nlohmann::ordered_json::parse(edited), plan.binUri);
    }

    // The side files first, so the scene never refers to a file not yet there.
    CreatedPaths created;
    for (const SideFile& side : plan.sideFiles) {
        if (side.alreadyThere) continue;
        created.createFoldersFor(side.destination);
        const bool existed = fs::exists(side.destination);
        engine::writeFileAtomically(side.destination, side.bytes.empty()
                                                           ? engine::readWholeFile(side.source, "a file the scene refers to")
                                                           : side.bytes);
        if (!existed) created.add(side.destination);
    }
    engine::writeFileAtomically(out, result);
    created.keep();
}

} // namespace tools
