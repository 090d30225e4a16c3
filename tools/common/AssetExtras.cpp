#include "AssetExtras.h"

#include "JsonEdits.h"
#include "SceneContainers.h"

#include "engine/util/Error.h"
#include "engine/util/InputFile.h"

#include <stdexcept>

namespace tools {

std::string setAssetExtras(const std::string& json, const std::map<std::string, nlohmann::json>& extras,
                           const std::string& fileName) {
    if (extras.empty()) return json;
    nlohmann::json expected = nlohmann::json::parse(json);
    const JsonSpan root = scanJson(json);
    const JsonSpan* asset = root.member("asset");
    // The loader refuses a file without an asset object, so this is a file edited since.
    if (!asset || asset->kind != '{') engine::throwInputError(fileName, "asset", "is not an object");
    const JsonSpan* assetExtras = asset->member("extras");
    if (assetExtras && assetExtras->kind != '{') engine::throwInputError(fileName, "asset.extras", "is not an object");
    std::vector<JsonEdit> edits;
    if (!assetExtras) {
        edits.push_back(appendMember(*asset, "extras", nlohmann::json(extras).dump()));
    } else {
        for (const auto& [key, value] : extras) {
            if (const JsonSpan* old = assetExtras->member(key)) edits.push_back({old->begin, old->end, value.dump()});
            else edits.push_back(appendMember(*assetExtras, key, value.dump()));
        }
    }
    for (const auto& [key, value] : extras) expected["asset"]["extras"][key] = value;
    std::string out = applyJsonEdits(json, std::move(edits));
    if (nlohmann::json::parse(out) != expected)
        throw std::logic_error("recording asset.extras in " + fileName + " changed more than those members");
    return out;
}

nlohmann::json tunedSizeRecord(const TunedSize& size) { return {{"width", size.width}, {"height", size.height}}; }

std::optional<TunedSize> tunedSize(const nlohmann::json& document) {
    const auto asset = document.find("asset");
    if (asset == document.end() || !asset->is_object()) return std::nullopt;
    const auto extras = asset->find("extras");
    if (extras == asset->end() || !extras->is_object()) return std::nullopt;
    const auto tuned = extras->find(kTunedForKey);
    if (tuned == extras->end() || !tuned->is_object()) return std::nullopt;
    const auto width = tuned->find("width"), height = tuned->find("height");
    if (width == tuned->end() || height == tuned->end() || !width->is_number_integer() || !height->is_number_integer())
        return std::nullopt;
    const TunedSize size{width->get<int>(), height->get<int>()};
    if (size.width <= 0 || size.height <= 0) return std::nullopt;
    return size;
}

std::optional<TunedSize> readTunedSize(const std::filesystem::path& scene) {
    try {
        std::string json = engine::readWholeFile(scene, "the scene");
        if (json.size() >= 20 && json.compare(0, 4, "glTF") == 0) json = splitGlb(json, scene.string()).json;
        const nlohmann::json document = nlohmann::json::parse(json, nullptr, false);
        return document.is_discarded() ? std::nullopt : tunedSize(document);
    } catch (const engine::InputError&) {
        return std::nullopt;
    }
}

bool farFromTunedSize(const TunedSize& tuned, int width, int height) {
    const double ratio = (static_cast<double>(width) * height) / (static_cast<double>(tuned.width) * tuned.height);
    return ratio > 2.0 || ratio < 0.5;
}

} // namespace tools
