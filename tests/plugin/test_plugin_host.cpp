// Plugin host: the good plugin registers a pass that runs; every broken plugin is refused
// with one error naming the library and the reason, and nothing stays loaded.
#include "engine/plugin/PluginHost.h"

#include <engine_plugin/PluginAbi.h>
#include "engine/render/Frame.h"
#include "engine/render/SceneGpu.h"
#include "engine/scene/Scene.h"
#include "engine/util/Error.h"

#include <gtest/gtest.h>

#include <dlfcn.h>
#include <filesystem>
#include <fstream>

namespace {

const std::vector<std::filesystem::path> kDirs{TEST_PLUGIN_DIR};

struct NoTextures final : engine::ResourceAllocator {
    std::uint32_t acquire(const engine::TextureDesc&) override { return 1; }
    void release(std::uint32_t, const engine::TextureDesc&) override {}
};

std::string loadError(const std::string& library, nlohmann::json settings = nlohmann::json::object()) {
    engine::PluginHost host;
    try {
        host.load({library, settings}, kDirs);
    } catch (const engine::InputError& error) {
        EXPECT_TRUE(host.renderPlugins().empty());
        return error.what();
    }
    ADD_FAILURE() << library << " loaded but should have been refused";
    return {};
}

bool isLoaded(const std::string& file) {
    const std::string path = std::string(TEST_PLUGIN_DIR) + "/" + file;
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_NOLOAD);
    if (handle) dlclose(handle);
    return handle != nullptr;
}

} // namespace

TEST(PluginHost, GoodPluginRegistersAPassThatExecutes) {
    engine::PluginHost host;
    host.load({"good_plugin", {{"marker", "hello"}}}, kDirs);
    ASSERT_EQ(host.renderPlugins().size(), 1u);
    EXPECT_EQ(host.loadedNames(), std::vector<std::string>{"marker"});
    // Found by the library's name in the config, which --set uses, not by its own name.
    EXPECT_EQ(host.renderPlugins("good_plugin"), host.renderPlugins());
    EXPECT_TRUE(host.renderPlugins("marker").empty());

    engine::Scene scene;
    engine::SceneGpu gpu(scene);  // empty scene: no GL needed
    engine::RenderGraph graph;
    engine::Frame frame(scene, gpu, graph, {}, 0);
    host.renderPlugins()[0]->addPasses(frame);
    NoTextures allocator;
    graph.execute(allocator);

    ASSERT_EQ(graph.reports().size(), 1u);
    EXPECT_EQ(graph.reports()[0].name, "marker_hello");
    EXPECT_FALSE(graph.reports()[0].culled);
    EXPECT_EQ(graph.reports()[0].triangles, 7u);
    EXPECT_EQ(host.renderPlugins()[0]->frameStats()["executions"], 1);
}

TEST(PluginHost, UnloadsTheLibraryWhenDestroyed) {
    {
        engine::PluginHost host;
        host.load({"good_plugin", {}}, kDirs);
        EXPECT_TRUE(isLoaded("good_plugin.so"));
    }
    EXPECT_FALSE(isLoaded("good_plugin.so"));
}

TEST(PluginHost, MissingLibraryNamesItAndTheFoldersSearched) {
    const std::string message = loadError("no_such_plugin");
    EXPECT_NE(message.find("no_such_plugin.so"), std::string::npos) << message;
    EXPECT_NE(message.find("not found"), std::string::npos) << message;
    EXPECT_NE(message.find(TEST_PLUGIN_DIR), std::string::npos) << message;
}

TEST(PluginHost, MissingEntryPointIsRefused) {
    const std::string message = loadError("no_entry_plugin");
    EXPECT_NE(message.find("no_entry_plugin.so"), std::string::npos) << message;
    EXPECT_NE(message.find("no entry point engine_plugin_entry"), std::string::npos) << message;
    EXPECT_FALSE(isLoaded("no_entry_plugin.so"));
}

TEST(PluginHost, AbiMismatchIsRefusedBeforeRegistering) {
    const std::string message = loadError("old_abi_plugin");
    EXPECT_NE(message.find("old_abi_plugin.so"), std::string::npos) << message;
    // The fixture declares the engine's version + 41, whatever the engine's is.
    const std::string declared = "ABI version " + std::to_string(ENGINE_PLUGIN_ABI_VERSION + 41u);
    const std::string needed = "the engine needs " + std::to_string(ENGINE_PLUGIN_ABI_VERSION);
    EXPECT_NE(message.find(declared), std::string::npos) << message;
    EXPECT_NE(message.find(needed), std::string::npos) << message;
    EXPECT_FALSE(isLoaded("old_abi_plugin.so"));
}

TEST(PluginHost, WrongInterfaceIsRefused) {
    const std::string message = loadError("wrong_interface_plugin");
    EXPECT_NE(message.find("org.example.Other/3.0"), std::string::npos) << message;
}

TEST(PluginHost, ExceptionWhileRegisteringIsReportedAndUnloaded) {
    const std::string message = loadError("throwing_plugin");
    EXPECT_NE(message.find("throwing_plugin.so"), std::string::npos) << message;
    EXPECT_NE(message.find("the frobnicator is not calibrated"), std::string::npos) << message;
    EXPECT_FALSE(isLoaded("throwing_plugin.so"));
}

TEST(PluginHost, UnresolvedSymbolFailsAtLoadTime) {
    const std::string message = loadError("missing_symbol_plugin");
    EXPECT_NE(message.find("function_that_does_not_exist_anywhere"), std::string::npos) << message;
}

TEST(PluginHost, UnknownSettingIsRefusedByThePlugin) {
    const std::string message = loadError("good_plugin", {{"colour", "red"}});
    EXPECT_NE(message.find("unknown setting \"colour\""), std::string::npos) << message;
}

TEST(PluginHost, FileThatIsNotASharedObjectIsRefused) {
    const auto dir = std::filesystem::temp_directory_path() / "engine_plugin_test_fake";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "fake_plugin.so") << "this is text, not ELF\n";
    engine::PluginHost host;
    try {
        host.load({"fake_plugin", {}}, {dir});
        FAIL() << "a text file was loaded as a plugin";
    } catch (const engine::InputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("fake_plugin.so"), std::string::npos) << message;
        EXPECT_NE(message.find("cannot load plugin"), std::string::npos) << message;
    }
    std::filesystem::remove_all(dir);
}

TEST(PluginHost, LibraryIsOnlySearchedInTheGivenFolders) {
    // good_plugin exists in TEST_PLUGIN_DIR, but the host is told to look elsewhere only.
    engine::PluginHost host;
    EXPECT_THROW(host.load({"good_plugin", {}}, {std::filesystem::temp_directory_path()}),
                 engine::InputError);
}
