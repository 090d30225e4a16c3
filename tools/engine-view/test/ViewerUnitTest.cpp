// engine-view without a window: saving settings (in place, every other byte kept; elsewhere,
// with the files the scene refers to; as the other container), the script grammar and its
// errors, and the per-light edits the keys make.
#include "Controls.h"
#include "DebugViews.h"
#include "DepthImage.h"
#include "JsonSpans.h"
#include "OverlayText.h"
#include "Playback.h"
#include "SaveSettings.h"
#include "SceneContainers.h"
#include "Script.h"
#include "ViewerState.h"

#include "engine/gltf/GltfLoader.h"
#include "engine/util/Error.h"

#include "shadowmap/ShadowSettings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include <unistd.h>

namespace engine_view {

// The settings editor lives in tools/common since shadowmap-tune writes through it too.
using tools::JsonSpan;
using tools::replaceLightShadows;
using tools::saveSceneSettings;
using tools::scanJson;

namespace {

const char* const kGltf = R"({
  "asset": {"version": "2.0"},
  "extensions": {"KHR_lights_punctual": {"lights": [
    {"name": "a", "type": "point",
     "extras": {"shadow": {"variant": "standard",
                           "resolution": 2048}}},
    {"name": "b", "type": "spot", "spot": {"outerConeAngle": 0.5}},
    {"name": "c", "type": "directional", "extras": {}},
    {"name": "d", "type": "point", "extras": {"note": "keep me"}}
  ]}},
  "buffers": [{"uri": "data:application/octet-stream;base64,AAAA", "byteLength": 3}]
}
)";

nlohmann::json lightsOf(const std::string& text) {
    return nlohmann::json::parse(text)["extensions"]["KHR_lights_punctual"]["lights"];
}

std::string readAll(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::stringstream bytes;
    bytes << file.rdbuf();
    return bytes.str();
}

std::filesystem::path scratchDir() {
    return std::filesystem::temp_directory_path() / ("engine_view_unit_" + std::to_string(::getpid()));
}

// Removes the scratch folder when the test program ends.
struct ScratchCleanup {
    ~ScratchCleanup() {
        std::error_code ignored;
        std::filesystem::remove_all(scratchDir(), ignored);
    }
} scratchCleanup;

std::filesystem::path scratch(const std::string& name) {
    std::filesystem::create_directories(scratchDir() / "other");
    return scratchDir() / name;
}

} // namespace

TEST(JsonSpans, RecordsWhereEachValueLies) {
    const std::string text = R"( {"k\u0065y": [1, "two", {"x": null}], "n": -1.5e3} )";
    const JsonSpan root = scanJson(text);
    ASSERT_EQ(root.kind, '{');
    const JsonSpan* list = root.member("key");  // escaped keys are decoded
    ASSERT_NE(list, nullptr);
    ASSERT_EQ(list->items.size(), 3u);
    EXPECT_EQ(text.substr(list->items[1].begin, list->items[1].end - list->items[1].begin), "\"two\"");
    EXPECT_EQ(text.substr(root.member("n")->begin, root.member("n")->end - root.member("n")->begin), "-1.5e3");
    EXPECT_THROW(scanJson("{\"a\": }"), std::invalid_argument);
}

TEST(SaveSettings, ReplacesOnlyTheShadowObjects) {
    const nlohmann::json a = {{"variant", "woo"}, {"resolution", 1024}};
    const nlohmann::json b = {{"variant", "none"}};
    const nlohmann::json c = {{"dimming", 0.25}};
    const nlohmann::json d = {{"filter", "nearest"}};
    const std::string out = replaceLightShadows(kGltf, {{0, a}, {1, b}, {2, c}, {3, d}}, "test.gltf");
    const nlohmann::json lights = lightsOf(out);
    EXPECT_EQ(lights[0]["extras"]["shadow"], a);  // replaced
    EXPECT_EQ(lights[1]["extras"]["shadow"], b);  // extras inserted
    EXPECT_EQ(lights[2]["extras"]["shadow"], c);  // into an empty extras
    EXPECT_EQ(lights[3]["extras"]["shadow"], d);  // beside other extras
    EXPECT_EQ(lights[3]["extras"]["note"], "keep me");
    // Byte for byte: the text before the first edit and after the last is untouched.
    const std::string original = kGltf;
    const std::size_t head = original.find("{\"variant\": \"standard\"");
    EXPECT_EQ(out.substr(0, head), original.substr(0, head));
    const std::size_t tail = original.find("\n  ]}}");
    EXPECT_EQ(out.substr(out.size() - (original.size() - tail)), original.substr(tail));
}

TEST(SaveSettings, UnknownLightIsAnInputError) {
    EXPECT_THROW(replaceLightShadows(kGltf, {{7, nlohmann::json::object()}}, "test.gltf"), engine::InputError);
}

TEST(SaveSettings, GlbKeepsItsBinaryChunk) {
    const std::string json = R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":8}],)"
                             R"("extensions":{"KHR_lights_punctual":{"lights":[{"type":"spot"}]}}})";
    std::string padded = json;
    padded.append((4 - padded.size() % 4) % 4, ' ');
    const std::string bin("\x01\x02\x03\x04\x05\x06\x07\x08", 8);
    const auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
    const std::string glb = "glTF" + u32(2) + u32(12 + 8 + padded.size() + 8 + 8) + u32(padded.size()) + "JSON" +
                            padded + u32(8) + std::string("BIN\0", 4) + bin;
    const auto scene = scratch("model.glb");
    std::ofstream(scene, std::ios::binary) << glb;
    saveSceneSettings(scene, scratch("other/model.glb"), {{0, {{"resolution", 512}}}});
    const std::string out = readAll(scratch("other/model.glb"));
    ASSERT_GE(out.size(), 20u);
    std::uint32_t total = 0, jsonLength = 0;
    std::memcpy(&total, out.data() + 8, 4);
    std::memcpy(&jsonLength, out.data() + 12, 4);
    EXPECT_EQ(total, out.size());
    EXPECT_EQ(jsonLength % 4, 0u);
    EXPECT_EQ(lightsOf(out.substr(20, jsonLength))[0]["extras"]["shadow"]["resolution"], 512);
    EXPECT_EQ(out.substr(20 + jsonLength), glb.substr(20 + padded.size()));  // BIN chunk as it was
}

namespace {

const std::filesystem::path kScenes = std::filesystem::path(CONTENT_DIR) / "scenes";

// A fresh empty folder under the scratch folder.
std::filesystem::path freshFolder(const std::string& name) {
    const auto folder = scratch(name);
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

// showcase.gltf and its showcase.bin in a folder of their own.
std::filesystem::path showcaseIn(const std::string& folderName) {
    const auto folder = freshFolder(folderName);
    for (const char* name : {"showcase.gltf", "showcase.bin"})
        std::filesystem::copy_file(kScenes / name, folder / name);
    return folder / "showcase.gltf";
}

std::string base64Decode(const std::string& text) {
    const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string bytes;
    std::uint32_t bits = 0;
    int count = 0;
    for (char c : text) {
        const std::size_t value = alphabet.find(c);
        if (value == std::string::npos) break;
        bits = (bits << 6) | static_cast<std::uint32_t>(value);
        if ((count += 6) >= 8) {
            count -= 8;
            bytes += static_cast<char>((bits >> count) & 0xFF);
        }
    }
    return bytes;
}

// masked_fence.gltf (a textured scene) with its data-URI image moved to the file
// "textures/fence mask+1.png": a sub-folder, and a name whose URI needs escapes ('+' would
// read as a space), so a copy must keep the URI and land at the decoded path.
std::filesystem::path texturedFenceIn(const std::string& folderName) {
    const auto folder = freshFolder(folderName);
    std::filesystem::copy_file(kScenes / "masked_fence.bin", folder / "masked_fence.bin");
    nlohmann::ordered_json document = nlohmann::ordered_json::parse(readAll(kScenes / "masked_fence.gltf"));
    const std::string uri = document["images"][0]["uri"];
    std::filesystem::create_directories(folder / "textures");
    std::ofstream(folder / "textures" / "fence mask+1.png", std::ios::binary)
        << base64Decode(uri.substr(uri.find(',') + 1));
    document["images"][0]["uri"] = "textures/fence%20mask%2B1.png";
    document["images"][0].erase("mimeType");  // a GLB needs one: taken from the PNG's bytes then
    std::ofstream(folder / "fence.gltf") << document.dump(2);
    return folder / "fence.gltf";
}

// The saved scene loads to the original, light `edited` excepted, whose extras.shadow is
// `shadow`. Exact comparisons: a save copies or embeds the very bytes the original reads.
void expectSameScene(const std::filesystem::path& originalPath, const std::filesystem::path& savedPath, int edited,
                     const nlohmann::json& shadow) {
    const engine::Scene original = engine::loadGltf(originalPath);
    const engine::Scene saved = engine::loadGltf(savedPath);
    ASSERT_EQ(saved.meshes.size(), original.meshes.size());
    for (std::size_t m = 0; m < original.meshes.size(); ++m) {
        ASSERT_EQ(saved.meshes[m].primitives.size(), original.meshes[m].primitives.size());
        for (std::size_t p = 0; p < original.meshes[m].primitives.size(); ++p) {
            const engine::Primitive& a = original.meshes[m].primitives[p];
            const engine::Primitive& b = saved.meshes[m].primitives[p];
            EXPECT_EQ(b.positions.size(), a.positions.size()) << "mesh " << m << " primitive " << p;
            EXPECT_TRUE(b.positions == a.positions) << "mesh " << m << " primitive " << p;
            EXPECT_TRUE(b.normals == a.normals) << "mesh " << m << " primitive " << p;
            EXPECT_TRUE(b.texcoords == a.texcoords) << "mesh " << m << " primitive " << p;
            EXPECT_EQ(b.indices, a.indices) << "mesh " << m << " primitive " << p;
        }
    }
    EXPECT_EQ(saved.nodes.size(), original.nodes.size());
    ASSERT_EQ(saved.images.size(), original.images.size());
    for (std::size_t i = 0; i < original.images.size(); ++i) {
        EXPECT_EQ(saved.images[i].width, original.images[i].width);
        EXPECT_EQ(saved.images[i].rgba8, original.images[i].rgba8) << "image " << i;
    }
    ASSERT_EQ(saved.lights.size(), original.lights.size());
    for (std::size_t l = 0; l < original.lights.size(); ++l) {
        EXPECT_EQ(saved.lights[l].name, original.lights[l].name);
        EXPECT_EQ(saved.lights[l].type, original.lights[l].type);
        EXPECT_EQ(saved.lights[l].intensity, original.lights[l].intensity);
        EXPECT_EQ(saved.lights[l].color, original.lights[l].color);
        nlohmann::json extras = original.lights[l].extras;
        if (static_cast<int>(l) == edited) extras["shadow"] = shadow;
        EXPECT_EQ(saved.lights[l].extras, extras) << "light " << l;
    }
}

std::vector<std::string> filesUnder(const std::filesystem::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
        names.push_back(std::filesystem::relative(entry.path(), folder).string());
    std::sort(names.begin(), names.end());
    return names;
}

std::string errorOf(const std::function<void()>& action) {
    try {
        action();
    } catch (const engine::InputError& error) {
        return error.what();
    }
    return "no error";
}

const nlohmann::json kShadow = {{"variant", "woo"}, {"resolution", 512}};

} // namespace

TEST(SaveSettings, GltfSavedElsewhereTakesItsFilesAlong) {
    const auto scene = showcaseIn("showcase_src");
    const auto out = freshFolder("showcase_elsewhere") / "saved.gltf";
    tools::checkSaveTarget(scene, out);
    saveSceneSettings(scene, out, {{1, kShadow}});
    EXPECT_EQ(filesUnder(out.parent_path()), (std::vector<std::string>{"saved.gltf", "showcase.bin"}));
    EXPECT_EQ(readAll(out.parent_path() / "showcase.bin"), readAll(kScenes / "showcase.bin"));
    expectSameScene(scene, out, 1, kShadow);

    // Images too, into the sub-folder their URI names; the URI itself is kept.
    const auto fence = texturedFenceIn("fence_src");
    const auto fenceOut = freshFolder("fence_elsewhere") / "fence.gltf";
    saveSceneSettings(fence, fenceOut, {{0, kShadow}});
    EXPECT_EQ(filesUnder(fenceOut.parent_path()),
              (std::vector<std::string>{"fence.gltf", "masked_fence.bin", "textures", "textures/fence mask+1.png"}));
    EXPECT_EQ(nlohmann::json::parse(readAll(fenceOut))["images"][0]["uri"], "textures/fence%20mask%2B1.png");
    expectSameScene(fence, fenceOut, 0, kShadow);
}

TEST(SaveSettings, GltfSavedAsGlbEmbedsBuffersAndImages) {
    for (const auto& scene : {showcaseIn("glb_src"), texturedFenceIn("glb_fence_src"), kScenes / "masked_fence.gltf"}) {
        SCOPED_TRACE(scene.string());
        const auto out = freshFolder("glb_out") / "saved.glb";
        saveSceneSettings(scene, out, {{0, kShadow}});
        EXPECT_EQ(filesUnder(out.parent_path()), (std::vector<std::string>{"saved.glb"}));  // nothing beside it
        const std::string bytes = readAll(out);
        const tools::GlbChunks chunks = tools::splitGlb(bytes, out.string());
        const nlohmann::json document = nlohmann::json::parse(chunks.json);
        ASSERT_EQ(document["buffers"].size(), 1u);  // merged into the GLB-stored buffer
        EXPECT_FALSE(document["buffers"][0].contains("uri"));
        EXPECT_LE(document["buffers"][0]["byteLength"].get<std::size_t>(), chunks.bin.size());
        for (const nlohmann::json& image : document.value("images", nlohmann::json::array())) {
            EXPECT_FALSE(image.contains("uri"));
            EXPECT_EQ(image["mimeType"], "image/png");
        }
        for (const nlohmann::json& view : document["bufferViews"]) EXPECT_EQ(view["buffer"], 0);
        expectSameScene(scene, out, 0, kShadow);
    }
}

TEST(SaveSettings, DataUriBuffersAreDecodedIntoTheGlb) {
    // Two buffers, one a data URI (bytes 1 2 3) and one a file (4 bytes), each with a view:
    // merged, the second starts at the next multiple of 4 and its view's offset follows.
    const auto folder = freshFolder("data_uri_src");
    std::ofstream(folder / "four.bin", std::ios::binary) << "WXYZ";
    std::ofstream(folder / "data.gltf") << R"({"asset":{"version":"2.0"},
      "buffers":[{"uri":"data:application/octet-stream;base64,AQID","byteLength":3},{"uri":"four.bin","byteLength":4}],
      "bufferViews":[{"buffer":0,"byteLength":3},{"buffer":1,"byteOffset":1,"byteLength":3}],
      "extensions":{"KHR_lights_punctual":{"lights":[{"type":"point"}]}},"extensionsUsed":["KHR_lights_punctual"]})";
    const auto out = freshFolder("data_uri_out") / "data.glb";
    saveSceneSettings(folder / "data.gltf", out, {{0, kShadow}});
    const tools::GlbChunks chunks = tools::splitGlb(readAll(out), out.string());
    EXPECT_EQ(chunks.bin, std::string("\x01\x02\x03\0WXYZ", 8));
    const nlohmann::json document = nlohmann::json::parse(chunks.json);
    EXPECT_EQ(document["buffers"], nlohmann::json::parse(R"([{"byteLength":8}])"));
    EXPECT_EQ(document["bufferViews"], nlohmann::json::parse(R"([{"buffer":0,"byteLength":3,"byteOffset":0},
                                                                   {"buffer":0,"byteOffset":5,"byteLength":3}])"));
    EXPECT_EQ(engine::loadGltf(out).lights.at(0).extras["shadow"], kShadow);
}

TEST(SaveSettings, GlbSavedAsGltfWritesItsBinBeside) {
    const auto glb = freshFolder("glb_made") / "fence model.glb";
    saveSceneSettings(texturedFenceIn("gltf_fence_src"), glb, {});
    const auto out = freshFolder("gltf_out") / "fence+model.gltf";
    saveSceneSettings(glb, out, {{2, kShadow}});
    EXPECT_EQ(filesUnder(out.parent_path()), (std::vector<std::string>{"fence+model.bin", "fence+model.gltf"}));
    EXPECT_EQ(nlohmann::json::parse(readAll(out))["buffers"][0]["uri"], "fence%2Bmodel.bin");
    expectSameScene(glb, out, 2, kShadow);
    // Saved again over itself: the .bin beside it is the same, so it is left as it is.
    saveSceneSettings(glb, out, {{2, kShadow}});
    expectSameScene(glb, out, 2, kShadow);
}

TEST(SaveSettings, DifferentFileInTheWayIsRefused) {
    const auto scene = showcaseIn("way_src");
    const auto folder = freshFolder("way_out");
    std::ofstream(folder / "showcase.bin") << "the user's own file";
    const std::string message = errorOf([&] { tools::checkSaveTarget(scene, folder / "saved.gltf"); });
    EXPECT_NE(message.find((folder / "showcase.bin").string()), std::string::npos) << message;
    EXPECT_NE(message.find("a different file is already there"), std::string::npos) << message;
    EXPECT_EQ(errorOf([&] { saveSceneSettings(scene, folder / "saved.gltf", {{0, kShadow}}); }), message);
    EXPECT_EQ(readAll(folder / "showcase.bin"), "the user's own file");
    EXPECT_FALSE(std::filesystem::exists(folder / "saved.gltf"));
    // An identical file is no obstacle.
    std::filesystem::copy_file(kScenes / "showcase.bin", folder / "showcase.bin",
                               std::filesystem::copy_options::overwrite_existing);
    saveSceneSettings(scene, folder / "saved.gltf", {{0, kShadow}});
    expectSameScene(scene, folder / "saved.gltf", 0, kShadow);
}

TEST(SaveSettings, FileWhereASubFolderMustGoIsRefusedBeforeWriting) {
    const auto fence = texturedFenceIn("blocked_src");
    // A file where the image's sub-folder must go: nobody can write there, root included.
    const auto blocked = freshFolder("blocked_out");
    std::ofstream(blocked / "textures") << "in the way";
    const std::string message = errorOf([&] { saveSceneSettings(fence, blocked / "fence.gltf", {{0, kShadow}}); });
    EXPECT_NE(message.find("textures/fence mask+1.png"), std::string::npos) << message;
    EXPECT_NE(message.find("is not a folder"), std::string::npos) << message;
    EXPECT_EQ(filesUnder(blocked), (std::vector<std::string>{"textures"}));  // not even masked_fence.bin
    EXPECT_EQ(errorOf([&] { tools::checkSaveTarget(fence, blocked / "fence.gltf"); }), message);  // at start too
}

TEST(SaveSettings, ReadOnlyDestinationFolderIsRefusedBeforeWriting) {
    // access(2) grants root every folder, so only another user can see this refusal.
    if (::geteuid() == 0) GTEST_SKIP() << "root writes into read-only folders: the refusal needs another user";
    const auto fence = texturedFenceIn("read_only_src");
    const auto readOnly = freshFolder("read_only_out");
    std::filesystem::create_directories(readOnly / "textures");
    std::filesystem::permissions(readOnly / "textures", std::filesystem::perms::owner_read |
                                                            std::filesystem::perms::owner_exec);
    const std::string readOnlyMessage = errorOf([&] { saveSceneSettings(fence, readOnly / "fence.gltf", {}); });
    std::filesystem::permissions(readOnly / "textures", std::filesystem::perms::owner_all);
    EXPECT_NE(readOnlyMessage.find("is not writable"), std::string::npos) << readOnlyMessage;
    EXPECT_EQ(filesUnder(readOnly), (std::vector<std::string>{"textures"}));
}

TEST(SaveSettings, UriTheLoaderRefusesIsNeitherCopiedNorEmbedded) {
    const auto folder = freshFolder("escape_src");
    std::filesystem::create_directories(folder / "scene");
    std::ofstream(folder / "outside.bin") << "1234";
    const auto scene = folder / "scene" / "escape.gltf";
    std::ofstream(scene) << R"({"asset":{"version":"2.0"},"buffers":[{"uri":"../outside.bin","byteLength":4}],
      "extensions":{"KHR_lights_punctual":{"lights":[{"type":"point"}]}}})";
    const auto out = freshFolder("escape_out");
    for (const char* name : {"saved.gltf", "saved.glb"}) {
        const std::string message = errorOf([&] { saveSceneSettings(scene, out / name, {{0, kShadow}}); });
        EXPECT_NE(message.find("buffers[0]: uri '../outside.bin' climbs out of the scene's folder"), std::string::npos)
            << message;
    }
    EXPECT_TRUE(filesUnder(out).empty());
    // Saved beside it in the same container nothing is copied: the file keeps its URI as it was.
    saveSceneSettings(scene, folder / "scene" / "saved.gltf", {{0, kShadow}});
    EXPECT_EQ(lightsOf(readAll(folder / "scene" / "saved.gltf"))[0]["extras"]["shadow"], kShadow);
}

TEST(Script, ParsesCommandsAndSkipsComments) {
    const Script script = Script::parse("# setup\n\nkey V\nset sun polygon_offset [2, 6]\nview truth\nquit\n", "s.txt");
    EXPECT_EQ(script.size(), 4u);
}

TEST(Script, ErrorsNameTheFileAndLine) {
    const auto message = [](const std::string& text) {
        try {
            Script::parse(text, "s.txt");
        } catch (const engine::InputError& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message("key V\n\nfly away"),
              "s.txt:3: unknown command \"fly\" (known: camera, frames, key, orbit, overlay, pan, pause, play, "
              "quit, resize, save, screenshot, select, set, time, view, zoom)");
    EXPECT_EQ(message("frames 0"), "s.txt:1: frames: N must be an integer in [1, 100000]");
    EXPECT_EQ(message("key F13"), "s.txt:1: key: unknown key \"F13\"");
    EXPECT_EQ(message("set sun"), "s.txt:1: set: expected 3 or more argument(s), got 1");
    EXPECT_EQ(message("view up"), "s.txt:1: view: unknown view \"up\" (shaded, light, depth, projected, comparison, "
                                  "shadow, penumbra, truth, cascades, density)");
    EXPECT_EQ(message("overlay maybe"), "s.txt:1: overlay: expected on or off");
}

namespace {

engine::Scene twoLights() {
    engine::Scene scene;
    for (const char* name : {"key", "fill"}) {
        engine::Light light;
        light.name = name;
        light.type = engine::Light::Type::Spot;
        scene.lights.push_back(light);
        engine::Node node;
        node.name = name;
        node.light = static_cast<int>(scene.lights.size()) - 1;
        scene.roots.push_back(static_cast<int>(scene.nodes.size()));
        scene.nodes.push_back(node);
    }
    scene.lights[1].extras = {{"shadow", {{"near_plane", 0.5}, {"resolution", 4096}}}};
    scene.updateWorldTransforms();
    return scene;
}

} // namespace

TEST(ViewerState, KeysCycleTheSelectedLightsSettings) {
    engine::Scene scene = twoLights();
    ViewerState state(scene, {{"variant", "standard"}, {"resolution", 2048}});
    ASSERT_EQ(state.lights().size(), 2u);
    EXPECT_EQ(state.lights()[0].name, "key");
    state.cycleVariant();
    state.cycleVariant();
    EXPECT_EQ(scene.lights[0].extras["shadow"]["variant"], "backface");
    state.cycleResolution();  // 2048 (config) -> 4096
    EXPECT_EQ(scene.lights[0].extras["shadow"]["resolution"], 4096);
    state.selectNext();
    state.cycleResolution();  // 4096 (extras) -> 512
    EXPECT_EQ(scene.lights[1].extras["shadow"]["resolution"], 512);
    for (int i = 0; i < 3; ++i) state.addDimming(0.05);  // 0.4 -> 0.55, rounded to 0.01
    EXPECT_EQ(scene.lights[1].extras["shadow"]["dimming"], 0.55);
    state.toggleFilter();  // pcf -> vsm: pcss needs a size this light has not
    state.cycleDepthFormat();  // d24 -> d32f
    const nlohmann::json saved = state.savedShadow(1);
    // The variant was never chosen for this light: it stays the config's.
    EXPECT_EQ(saved, nlohmann::json({{"resolution", 512}, {"depth_format", "d32f"},
                                     {"filter", "vsm"}, {"dimming", 0.55}, {"near_plane", 0.5}}));
    EXPECT_TRUE(state.select("key"));
    EXPECT_FALSE(state.select("moon"));
    EXPECT_EQ(state.selected(), 0);
}

TEST(ViewerState, SavesOnlyWhatDiffersFromTheDefaults) {
    // A light the file gave no settings: what the viewer set back to the defaults' value
    // (the config's resolution, the built-in dimming and depth format) is left out, so a
    // later config change still reaches it; the file's own keys stay as they are now.
    engine::Scene scene = twoLights();
    ViewerState state(scene, {{"variant", "standard"}, {"resolution", 1024}, {"cache_maps", true}});
    state.set(0, "variant", "woo");
    state.set(0, "resolution", 1024);
    state.set(0, "dimming", 0.4);
    state.set(0, "depth_format", "d24");
    EXPECT_EQ(state.savedShadow(0), nlohmann::json({{"variant", "woo"}}));
    state.set(1, "resolution", 1024);  // the file's key, now equal to the config's: kept
    EXPECT_EQ(state.savedShadow(1), nlohmann::json({{"near_plane", 0.5}, {"resolution", 1024}}));
}

TEST(ViewerState, KeysCycleThroughWhatThePluginAccepts) {
    // Starting from the plugin's defaults (no config, no extras), each key visits every
    // allowed value of the settings API once, in its order, and comes back.
    engine::Scene scene = twoLights();
    ViewerState state(scene, nlohmann::json::object());
    const auto visit = [&](const char* key, auto cycle) {
        std::vector<nlohmann::json> seen = {state.effective(0)[key]};
        for (std::size_t i = 0; i < 8 && (seen.size() == 1 || seen.back() != seen.front()); ++i) {
            (state.*cycle)();
            seen.push_back(scene.lights[0].extras["shadow"][key]);
        }
        seen.pop_back();  // back at the start
        return seen;
    };
    const auto rotatedFrom = [](std::vector<std::string> values, const std::string& first) {
        std::rotate(values.begin(), std::find(values.begin(), values.end(), first), values.end());
        return std::vector<nlohmann::json>(values.begin(), values.end());
    };
    const shadowmap::ShadowSettings defaults;
    const std::vector<nlohmann::json> variants = visit("variant", &ViewerState::cycleVariant);
    EXPECT_EQ(variants, rotatedFrom(shadowmap::settingKey("variant").choices, shadowmap::toString(defaults.variant)));
    // Shadow volumes too (no map: exact per pixel).
    EXPECT_NE(std::find(variants.begin(), variants.end(), nlohmann::json("volume")), variants.end());
    EXPECT_EQ(visit("depth_format", &ViewerState::cycleDepthFormat),
              rotatedFrom(shadowmap::settingKey("depth_format").choices, shadowmap::toString(defaults.depthFormat)));
    // Without a size the light takes every filter but pcss: the key skips it.
    std::vector<std::string> withoutPcss = shadowmap::settingKey("filter").choices;
    withoutPcss.erase(std::find(withoutPcss.begin(), withoutPcss.end(), shadowmap::toString(shadowmap::Filter::Pcss)));
    EXPECT_EQ(visit("filter", &ViewerState::toggleFilter), rotatedFrom(withoutPcss, shadowmap::toString(defaults.filter)));
    // With one it visits every filter.
    state.set(0, "light_radius", 0.1);
    EXPECT_EQ(visit("filter", &ViewerState::toggleFilter),
              rotatedFrom(shadowmap::settingKey("filter").choices, shadowmap::toString(defaults.filter)));
    EXPECT_EQ(visit("resolution", &ViewerState::cycleResolution),
              (std::vector<nlohmann::json>{2048, 4096, 512, 1024}));
    EXPECT_EQ(visit("cascades", &ViewerState::cycleCascades), (std::vector<nlohmann::json>{"auto", 1, 2, 3, 4}));
    EXPECT_EQ(visit("stable", &ViewerState::toggleStable), (std::vector<nlohmann::json>{true, false}));
    EXPECT_EQ(state.effective(0)["dimming"], 0.4);
}

namespace {

// Whether the plugin takes light `index`'s settings as the viewer holds them: its own keys
// (a light sized by its type's key) and the effective settings (pcss only with a size).
void expectAccepted(ViewerState& state, const engine::Scene& scene, int index) {
    const engine::Light::Type type = state.lights()[index].type;
    const nlohmann::json& own = scene.lights[state.lights()[index].light].extras["shadow"];
    EXPECT_NO_THROW(shadowmap::checkSizeKeyForType(own, type, "test", "shadow")) << own;
    EXPECT_NO_THROW(shadowmap::checkFilterForType(shadowmap::parseSettings(state.effective(index), "test", "shadow"),
                                                  type, "test", "shadow"))
        << state.effective(index);
}

} // namespace

TEST(ViewerState, SizeStepsReachZeroAndLeaveIt) {
    using Type = engine::Light::Type;
    for (const Type type : {Type::Spot, Type::Point, Type::Directional}) {
        const double smallest = smallestLightSize(type);
        EXPECT_GT(smallest, 0.0);
        EXPECT_EQ(stepLightSize(0.0, type, true), smallest);
        EXPECT_EQ(stepLightSize(0.0, type, false), 0.0);  // clamped at 0
        EXPECT_EQ(stepLightSize(smallest, type, false), 0.0);
        EXPECT_EQ(stepLightSize(0.5 * smallest, type, false), 0.0);  // below the smallest: to 0
        EXPECT_EQ(stepLightSize(1.2 * smallest, type, false), smallest);  // not below the smallest before 0
        // A size off the keys' ladder (set by a script) steps to the next rung each way.
        const double off = 10.3 * smallest;
        EXPECT_GT(stepLightSize(off, type, true), off);
        EXPECT_LE(stepLightSize(off, type, true), off * kLightSizeStep);
        EXPECT_LT(stepLightSize(off, type, false), off);
        EXPECT_GE(stepLightSize(off, type, false), off / kLightSizeStep);
        // Steps multiply by kLightSizeStep, and a step down undoes a step up exactly.
        double size = smallest;
        std::vector<double> up = {size};
        for (int i = 0; i < 20; ++i) up.push_back(size = stepLightSize(size, type, true));
        for (std::size_t i = 1; i < up.size(); ++i) EXPECT_NEAR(up[i] / up[i - 1], kLightSizeStep, 1e-3);
        for (std::size_t i = up.size() - 1; i > 0; --i) EXPECT_EQ(stepLightSize(up[i], type, false), up[i - 1]);
    }
    EXPECT_STREQ(lightSizeKey(Type::Directional), "angular_diameter");
    EXPECT_STREQ(lightSizeKey(Type::Spot), "light_radius");
    EXPECT_STREQ(lightSizeKey(Type::Point), "light_radius");
}

TEST(ViewerState, SizeKeysSizeEachLightByItsType) {
    engine::Scene scene = twoLights();
    scene.lights[1].type = engine::Light::Type::Directional;
    ViewerState state(scene, nlohmann::json::object());
    const auto own = [&](int light) { return scene.lights[light].extras["shadow"]; };
    EXPECT_EQ(state.shrinkLightSize(), "");
    EXPECT_EQ(own(0)["light_radius"], 0.0);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(state.growLightSize(), "");
    EXPECT_EQ(own(0)["light_radius"].get<double>(),
              stepLightSize(stepLightSize(smallestLightSize(engine::Light::Type::Spot), engine::Light::Type::Spot, true),
                            engine::Light::Type::Spot, true));
    EXPECT_FALSE(own(0).contains("angular_diameter"));
    expectAccepted(state, scene, 0);
    state.selectNext();
    state.growLightSize();
    EXPECT_EQ(own(1)["angular_diameter"], smallestLightSize(engine::Light::Type::Directional));
    EXPECT_FALSE(own(1).contains("light_radius"));
    expectAccepted(state, scene, 1);
    EXPECT_EQ(own(0)["light_radius"].get<double>(), state.effective(0)["light_radius"].get<double>())
        << "the other light is left as it was";
}

TEST(ViewerState, ShrinkingAPcssLightToAPointFallsBackToPcf) {
    engine::Scene scene = twoLights();
    ViewerState state(scene, nlohmann::json::object());
    const std::string pcss = shadowmap::toString(shadowmap::Filter::Pcss), pcf = shadowmap::toString(shadowmap::Filter::Pcf);
    state.growLightSize();
    state.set(0, "filter", pcss);
    expectAccepted(state, scene, 0);
    const std::string note = state.shrinkLightSize();
    EXPECT_NE(note.find(pcf), std::string::npos) << note;
    EXPECT_NE(note.find("key"), std::string::npos) << note;  // names the light
    EXPECT_EQ(scene.lights[0].extras["shadow"]["light_radius"], 0.0);
    EXPECT_EQ(scene.lights[0].extras["shadow"]["filter"], pcf);
    expectAccepted(state, scene, 0);
    // Sized again, the filter stays pcf (P brings pcss back); a hard filter is left alone at 0.
    EXPECT_EQ(state.growLightSize(), "");
    EXPECT_EQ(scene.lights[0].extras["shadow"]["filter"], pcf);
    state.set(0, "filter", shadowmap::toString(shadowmap::Filter::Nearest));
    EXPECT_EQ(state.shrinkLightSize(), "");
    EXPECT_EQ(scene.lights[0].extras["shadow"]["filter"], shadowmap::toString(shadowmap::Filter::Nearest));
    expectAccepted(state, scene, 0);
}

TEST(Controls, SizeKeysHaveScriptNames) {
    EXPECT_GE(Controls::keyFromName("-"), 0);
    EXPECT_GE(Controls::keyFromName("="), 0);
    EXPECT_EQ(Controls::keyFromName("-"), Controls::keyFromName("minus"));
    EXPECT_EQ(Controls::keyFromName("="), Controls::keyFromName("equal"));
    EXPECT_NE(Controls::keyFromName("-"), Controls::keyFromName("="));
}

TEST(PenumbraView, TintsExactlyThePartlyLitPixelsAndDimsTheRest) {
    const std::vector<std::uint8_t> term = {0, 1, 128, 254, 255, 0};
    Image image{3, 2, {}};
    for (std::uint8_t value : {200, 30, 90, 255, 120, 0}) image.rgba.insert(image.rgba.end(), {value, value, value, 255});
    const Image shaded = image;
    EXPECT_EQ(paintPenumbra(image, term), 3u);
    for (std::size_t i = 0; i < term.size(); ++i) {
        const std::uint8_t* before = &shaded.rgba[4 * i];
        const std::uint8_t* after = &image.rgba[4 * i];
        EXPECT_EQ(inPenumbra(term[i]), term[i] > 0 && term[i] < 255);
        if (inPenumbra(term[i])) {
            // Magenta, wherever it falls: red and blue up, green down.
            EXPECT_GE(after[0], 128) << i;
            EXPECT_GE(after[2], 128) << i;
            EXPECT_LT(after[1], 128) << i;
        } else {
            for (int c = 0; c < 3; ++c) EXPECT_LT(after[c], 128) << i;  // dimmed
            for (int c = 0; c < 3; ++c) EXPECT_LE(after[c], before[c]) << i;
            EXPECT_EQ(after[0], after[1]) << i;  // the hue kept
        }
    }
}

TEST(OverlayText, ShowsTheLightsSizeInItsUnit) {
    EXPECT_EQ(OverlayText::lightSize(0.0, engine::Light::Type::Spot), "point");
    EXPECT_EQ(OverlayText::lightSize(0.0, engine::Light::Type::Directional), "point");
    EXPECT_EQ(OverlayText::lightSize(0.15, engine::Light::Type::Point), "size 0.15");
    EXPECT_EQ(OverlayText::lightSize(0.0093, engine::Light::Type::Directional), "size 0.0093 rad");
}

TEST(ViewerState, ViewsHaveNames) {
    for (int i = 0; i < kDebugViewCount; ++i)
        EXPECT_EQ(parseView(viewName(static_cast<DebugView>(i))), static_cast<DebugView>(i));
    EXPECT_FALSE(parseView("sideways"));
    EXPECT_EQ(parseView("penumbra"), DebugView::Penumbra);
    // D goes from the shadow term to its penumbra.
    engine::Scene scene = twoLights();
    ViewerState state(scene, nlohmann::json::object());
    state.setView(DebugView::ShadowTerm);
    state.nextView();
    EXPECT_EQ(state.view(), DebugView::Penumbra);
    // M: into the texel density and back to the view it left.
    EXPECT_EQ(parseView("density"), DebugView::TexelDensity);
    state.toggleTexelDensity();
    EXPECT_EQ(state.view(), DebugView::TexelDensity);
    state.toggleTexelDensity();
    EXPECT_EQ(state.view(), DebugView::Penumbra);
}

TEST(OverlayText, SaysWhereEachLightsShadeCameFrom) {
    engine::ShadeCacheReport shadeCache;
    shadeCache.layers = 1;
    shadeCache.fetched = {0, 2};
    shadeCache.computed = {1};
    shadeCache.constant = {3};
    EXPECT_EQ(OverlayText::shadeSource(shadeCache, 0), "shade reused");
    EXPECT_EQ(OverlayText::shadeSource(shadeCache, 1), "shade computed");
    EXPECT_EQ(OverlayText::shadeSource(shadeCache, 2), "shade reused");
    EXPECT_EQ(OverlayText::shadeSource(shadeCache, 3), "shade constant");
    engine::ShadeCacheReport other;
    other.uncached = {4};
    other.moving = {5};
    EXPECT_EQ(OverlayText::shadeSource(other, 4), "shade live");
    EXPECT_EQ(OverlayText::shadeSource(other, 5), "shade moving");
    EXPECT_EQ(OverlayText::shadeSource(shadeCache, 7), "");
    EXPECT_EQ(OverlayText::shadeSource({}, 0), "");
}

} // namespace engine_view

// The cube strip's face labels (engine-render --shadow-map, the depth view): each face
// carries its own name in its top-left corner, black on white, and nothing else changes but
// the one-pixel seam between faces.
// Debian's simple_skin: one animation over 0-5.5 s turning a skin joint.
TEST(Playback, SeeksPausesAndWrapsOverTheAnimationsSpan) {
    engine::Scene scene = engine::loadGltf("/usr/share/assimp/models/glTF2/simple_skin/simple_skin.gltf");
    ASSERT_EQ(scene.animations.size(), 1u);
    tools::AnimationPlayback choice;
    choice.animations = {0};
    engine_view::Playback playback(scene, choice);
    EXPECT_FALSE(playback.playing());
    EXPECT_EQ(playback.describe().rfind("animation: 0.00 s of 0.00-5.50 s, at rest", 0), 0u) << playback.describe();
    const engine::Aabb rest = scene.meshInstances.at(0).worldBounds;
    playback.seek(1.5);
    EXPECT_FALSE(scene.meshInstances.at(0).worldBounds == rest) << "the pose at 1.5 s bends the strip";
    EXPECT_EQ(playback.describe().rfind("animation: 1.50 s of 0.00-5.50 s, paused", 0), 0u) << playback.describe();
    EXPECT_FALSE(playback.advance(1.0)) << "a paused clock does not move";
    playback.setPlaying(true);
    ASSERT_TRUE(playback.advance(5.0));
    EXPECT_NEAR(playback.seconds(), 1.0, 1e-9);  // 1.5 + 5 = 6.5, wrapped over 5.5 s
    playback.seek(-2.0);
    EXPECT_EQ(playback.seconds(), 0.0);
    EXPECT_FALSE(playback.playing()) << "seeking pauses";

    engine::Scene still = engine::loadGltf("/usr/share/assimp/models/glTF2/simple_skin/simple_skin.gltf");
    engine_view::Playback none(still, tools::AnimationPlayback{});
    none.setPlaying(true);
    EXPECT_FALSE(none.playing());
    EXPECT_EQ(none.describe(), "");
}

TEST(DepthImage, CubeFacesAreLabelledInTheirCorners) {
    constexpr int kFace = 64, kWidth = 6 * kFace, kHeight = 64;
    std::vector<std::uint8_t> gray(kWidth * kHeight, 128);
    labelCubeFaces(gray, kWidth, kHeight, kFace);
    std::vector<std::vector<std::uint8_t>> corners;
    for (int face = 0; face < 6; ++face) {
        std::vector<std::uint8_t> corner;
        int black = 0;
        for (int y = 0; y < 12; ++y)
            for (int x = 1; x < 20; ++x) {
                corner.push_back(gray[y * kWidth + face * kFace + x]);
                black += corner.back() == 0;
            }
        EXPECT_GT(black, 8) << kCubeFaceNames[face];  // a glyph stroke is 1-3 pixels: 2 glyphs have more
        for (const std::vector<std::uint8_t>& other : corners) EXPECT_NE(corner, other) << kCubeFaceNames[face];
        corners.push_back(corner);
        // Below the label the depths are untouched (the seam column aside).
        for (int y = 20; y < kHeight; ++y)
            for (int x = 1; x < kFace; ++x) ASSERT_EQ(gray[y * kWidth + face * kFace + x], 128);
    }
}
