#include "TuneShards.h"

#include "engine/util/Error.h"
#include "engine/util/InputFile.h"

#include <filesystem>

namespace shadowmap_tune {

namespace {

// Scenes are compared by their absolute, normalized paths: shards may be given the same
// file by different relative paths.
std::string sceneKey(const std::string& scene) {
    std::error_code error;
    return std::filesystem::weakly_canonical(std::filesystem::absolute(scene), error).string();
}

} // namespace

std::string partialResult(const std::string& scene, const tools::Shard& shard, const nlohmann::json& tunedFor,
                          const std::map<int, nlohmann::json>& shadows) {
    nlohmann::json lights = nlohmann::json::object();
    for (const auto& [index, shadow] : shadows) lights[std::to_string(index)] = shadow;
    const nlohmann::json result = {{"scene", sceneKey(scene)}, {"shard", shard.index},   {"of", shard.count},
                                   {"tuned_for", tunedFor},      {"lights", lights}};
    return result.dump(2) + "\n";
}

MergedResult mergePartialResults(const std::vector<std::string>& files, const std::string& scene) {
    MergedResult merged;
    std::map<int, nlohmann::json>& shadows = merged.shadows;
    std::vector<bool> seen;
    int count = 0;
    for (const std::string& file : files) {
        const nlohmann::json part =
            nlohmann::json::parse(engine::readWholeFile(file, "the partial result"), nullptr, false);
        int index = 0, of = 0;
        nlohmann::json tunedFor;
        try {
            index = part.at("shard").get<int>();
            of = part.at("of").get<int>();
            tunedFor = part.at("tuned_for");
            if (part.at("scene").get<std::string>() != sceneKey(scene))
                engine::throwInputError(file, "", "is a partial result for " + part.at("scene").get<std::string>() +
                                                      ", not for " + sceneKey(scene));
            if (index < 1 || index > of) throw std::out_of_range("shard out of range");
        } catch (const std::exception& error) {
            if (dynamic_cast<const engine::InputError*>(&error)) throw;
            engine::throwInputError(file, "", std::string("not a shadowmap-tune --shard result: ") + error.what());
        }
        if (count == 0) {
            count = of;
            seen.assign(count, false);
            merged.tunedFor = tunedFor;
        } else if (of != count) {
            engine::throwInputError(file, "", "is shard " + std::to_string(index) + " of " + std::to_string(of) +
                                                  ", the others are of " + std::to_string(count));
        } else if (tunedFor != merged.tunedFor) {
            engine::throwInputError(file, "", "was tuned for " + tunedFor.dump() + ", the others for " +
                                                  merged.tunedFor.dump() + " (give every shard the same --width and --height)");
        }
        if (seen[index - 1]) engine::throwInputError(file, "", "shard " + std::to_string(index) + " given twice");
        seen[index - 1] = true;
        for (const auto& [light, shadow] : part.at("lights").items()) shadows[std::stoi(light)] = shadow;
    }
    for (int k = 0; k < count; ++k)
        if (!seen[k])
            throw engine::InputError("--merge: shard " + std::to_string(k + 1) + "/" + std::to_string(count) +
                                     " missing: no file written");
    if (count == 0) throw engine::InputError("--merge: no partial results given");
    return merged;
}

} // namespace shadowmap_tune
