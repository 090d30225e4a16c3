#include "SaveSettings.h"

#include "JsonEdits.h"

#include "engine/util/Error.h"
#include "engine/util/InputFile.h"
#include "engine/util/OutputFile.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>


namespace tools {

namespace {

std::uint32_t readU32(const std::string& bytes, std::size_t at) {
    std::uint32_t value = 0;
    for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(bytes[at + i]);
    return value;
}

void writeU32(std::string& bytes, std::size_t at, std::uint32_t value) {
    for (int i = 0; i < 4; ++i) bytes[at + i] = static_cast<char>((value >> (8 * i)) & 0xFF);
}

bool hasExtension(const std::filesystem::path& path, const char* extension) {
    std::string text = path.extension().string();
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text == extension;
}

// URIs of buffers and images that name files (not data: URIs).
std::vector<std::string> externalUris(const nlohmann::json& document) {
    std::vector<std::string> uris;
    for (const char* list : {"buffers", "images"})
        if (document.contains(list) && document[list].is_array())
            for (const nlohmann::json& entry : document[list])
                if (entry.is_object() && entry.contains("uri") && entry["uri"].is_string() &&
                    entry["uri"].get<std::string>().rfind("data:", 0) != 0)
                    uris.push_back(entry["uri"]);
    return uris;
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

// The scene as saveSceneSettings edits it: its bytes, container and JSON text.
struct SceneFile {
    std::string bytes;
    bool glb = false;
    std::string json;
    std::size_t jsonLength = 0;  // .glb: the JSON chunk's length
};

SceneFile readScene(const std::filesystem::path& scene) {
    SceneFile file;
    file.bytes = engine::readWholeFile(scene, "the scene");
    file.glb = file.bytes.size() >= 20 && file.bytes.compare(0, 4, "glTF") == 0;
    if (file.glb) {
        file.jsonLength = readU32(file.bytes, 12);
        if (file.bytes.compare(16, 4, "JSON") != 0 || 20 + file.jsonLength > file.bytes.size())
            engine::throwInputError(scene.string(), "GLB", "the first chunk is not a JSON chunk");
        file.json = file.bytes.substr(20, file.jsonLength);
    } else {
        file.json = file.bytes;
    }
    return file;
}

// Everything that would make saving `file` (loaded from `scene`) to `out` fail, short of
// the write itself.
void checkTarget(const std::filesystem::path& scene, const SceneFile& file, const std::filesystem::path& out) {
    if (file.glb != hasExtension(out, ".glb"))
        engine::throwInputError(out.string(), "", std::string("the scene is a ") + (file.glb ? ".glb" : ".gltf") +
                                                     ": save it as one too (the file keeps its container)");
    engine::checkOutputPath(out);
    std::error_code error;

    const nlohmann::json document = nlohmann::json::parse(file.json, nullptr, false);
    if (document.is_discarded()) engine::throwInputError(scene.string(), "", "the JSON no longer parses");
    const std::vector<std::string> uris = externalUris(document);
    if (!uris.empty()) {
        const auto canonicalFolder = [&](const std::filesystem::path& path) {
            return std::filesystem::weakly_canonical(std::filesystem::absolute(path).parent_path(), error);
        };
        if (canonicalFolder(scene) != canonicalFolder(out))
            engine::throwInputError(out.string(), "",
                                    "the scene refers to external files (" + uris.front() +
                                        (uris.size() > 1 ? ", ..." : "") + ") by relative URI: save it in the "
                                        "scene's folder (" + std::filesystem::absolute(scene).parent_path().string() +
                                        ") so they still resolve");
    }
}

} // namespace

void checkSaveTarget(const std::filesystem::path& scene, const std::filesystem::path& out) {
    checkTarget(scene, readScene(scene), out);
}

void saveSceneSettings(const std::filesystem::path& scene, const std::filesystem::path& out,
                       const std::map<int, nlohmann::json>& shadows, const std::vector<AddedLight>& added) {
    const SceneFile file = readScene(scene);
    checkTarget(scene, file, out);
    const std::string& bytes = file.bytes;
    const std::string& json = file.json;
    const bool glb = file.glb;
    const std::size_t jsonLength = file.jsonLength;

    std::string edited = addLights(replaceLightShadows(json, shadows, scene.string()), added, scene.string());
    if (!glb) {
        engine::writeFileAtomically(out, edited);
        return;
    }
    edited.append((4 - edited.size() % 4) % 4, ' ');  // GLB chunks are 4-byte aligned, JSON padded with spaces
    std::string result = bytes.substr(0, 12);
    result.append(8, '\0');
    writeU32(result, 12, static_cast<std::uint32_t>(edited.size()));
    result.replace(16, 4, "JSON");
    result += edited;
    result += bytes.substr(20 + jsonLength);  // the BIN chunk (and any other) as it was
    writeU32(result, 8, static_cast<std::uint32_t>(result.size()));
    engine::writeFileAtomically(out, result);
}

} // namespace tools
