// Where the plugin host looks for plugins and where programs find the default config
// (docs/installing.md): the config's plugin_dirs, then ENGINE_PLUGIN_PATH, then the install's
// plugin folder beside libengine, then the build tree's. The winner is told apart by the
// plugin's own name: a copy of the "marker" fixture renamed shadowmap_plugin.so shadows the
// real shadow plugin of the build tree only when its folder comes first.
#include "engine/config/EngineConfig.h"
#include "engine/plugin/PluginHost.h"
#include "engine/util/Error.h"
#include "engine/util/InstallLayout.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

// A fresh folder per test, the environment variable unset before and after.
class PluginSearchOrder : public ::testing::Test {
protected:
    void SetUp() override {
        unsetenv("ENGINE_PLUGIN_PATH");
        dir_ = fs::temp_directory_path() / ("engine_plugin_search_" + std::to_string(getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        unsetenv("ENGINE_PLUGIN_PATH");
        fs::remove_all(dir_);
    }
    // The fixture `fixture`.so copied into dir_/sub as `library`.so.
    fs::path plant(const std::string& fixture, const std::string& sub, const std::string& library) {
        fs::create_directories(dir_ / sub);
        const fs::path target = dir_ / sub / (library + ".so");
        fs::copy_file(fs::path(TEST_PLUGIN_DIR) / (fixture + ".so"), target);
        return fs::canonical(target);
    }
    static engine::EngineConfig configLoading(const std::string& library) {
        engine::EngineConfig config;
        config.sourcePath = "search.json";
        config.plugins.push_back({library, nlohmann::json::object()});
        return config;
    }
    fs::path dir_;
};

TEST_F(PluginSearchOrder, EnvironmentPathIsSplitAtColonsInItsOrderSkippingEmptyEntries) {
    setenv("ENGINE_PLUGIN_PATH", ":/first::/second:", 1);
    EXPECT_EQ(engine::PluginHost::environmentPluginDirs(), (std::vector<fs::path>{"/first", "/second"}));
}

TEST_F(PluginSearchOrder, ConfigThenEnvironmentThenInstalledThenBuildTree) {
    setenv("ENGINE_PLUGIN_PATH", "/env/one:/env/two", 1);
    engine::EngineConfig config = configLoading("any");
    config.pluginDirs = {"/from/config"};
    // This test runs on the build tree's libengine, so the build tree's folder is the last.
    const std::vector<fs::path> expected{"/from/config", "/env/one", "/env/two",
                                         fs::path(ENGINE_BUILD_LIBRARY_DIR) / "shadow-engine/plugins",
                                         ENGINE_BUILD_PLUGIN_DIR};
    EXPECT_EQ(engine::PluginHost::searchDirectories(config), expected);
    EXPECT_EQ(engine::installedPluginDir(), expected[3]);
}

TEST_F(PluginSearchOrder, WithoutOtherFoldersTheBuildTreesPluginIsLoaded) {
    engine::PluginHost host;
    host.loadAll(configLoading("shadowmap_plugin"));
    ASSERT_EQ(host.loadedFiles().size(), 1u);
    EXPECT_EQ(host.loadedFiles()[0], fs::canonical(fs::path(ENGINE_BUILD_PLUGIN_DIR) / "shadowmap_plugin.so"));
}

TEST_F(PluginSearchOrder, EnvironmentFolderWinsOverTheBuildTree) {
    const fs::path planted = plant("good_plugin", "env", "shadowmap_plugin");
    setenv("ENGINE_PLUGIN_PATH", (dir_ / "env").c_str(), 1);
    engine::PluginHost host;
    host.loadAll(configLoading("shadowmap_plugin"));
    EXPECT_EQ(host.loadedNames(), std::vector<std::string>{"marker"});
    EXPECT_EQ(host.loadedFiles(), std::vector<fs::path>{planted});
}

TEST_F(PluginSearchOrder, ConfigFolderWinsOverTheEnvironment) {
    const fs::path fromConfig = plant("good_plugin", "config", "chosen");
    plant("gl_error_plugin", "env", "chosen");
    setenv("ENGINE_PLUGIN_PATH", (dir_ / "env").c_str(), 1);
    engine::EngineConfig config = configLoading("chosen");
    config.pluginDirs = {dir_ / "config"};
    engine::PluginHost host;
    host.loadAll(config);
    EXPECT_EQ(host.loadedNames(), std::vector<std::string>{"marker"});
    EXPECT_EQ(host.loadedFiles(), std::vector<fs::path>{fromConfig});
}

TEST_F(PluginSearchOrder, MissingPluginErrorListsEveryFolderTriedInOrder) {
    setenv("ENGINE_PLUGIN_PATH", "/env/one:/env/two", 1);
    engine::EngineConfig config = configLoading("no_such_plugin");
    config.pluginDirs = {"/from/config"};
    std::string message;
    try {
        engine::PluginHost().loadAll(config);
    } catch (const engine::InputError& error) {
        message = error.what();
    }
    ASSERT_NE(message.find("search.json: plugin \"no_such_plugin\": library no_such_plugin.so not found"),
              std::string::npos) << message;
    std::size_t previous = 0;
    for (const fs::path& dir : {fs::path("/from/config"), fs::path("/env/one"), fs::path("/env/two"),
                                engine::installedPluginDir(), fs::path(ENGINE_BUILD_PLUGIN_DIR)}) {
        const std::size_t at = message.find(dir.string(), previous);
        EXPECT_NE(at, std::string::npos) << dir << " missing or out of order in: " << message;
        if (at != std::string::npos) previous = at;
    }
}

// The default config: a checkout's content/engine.json under the current folder first.
class DefaultEngineConfig : public PluginSearchOrder {
protected:
    void SetUp() override {
        PluginSearchOrder::SetUp();
        previous_ = fs::current_path();
        fs::current_path(dir_);
    }
    void TearDown() override {
        fs::current_path(previous_);
        PluginSearchOrder::TearDown();
    }
    fs::path previous_;
};

TEST_F(DefaultEngineConfig, CheckoutContentIsFoundFromTheCurrentFolder) {
    fs::create_directories("content");
    std::ofstream("content/engine.json") << "{}";
    EXPECT_EQ(engine::findDefaultEngineConfig(), fs::path("content/engine.json"));
}

// A tool of the build tree started from any folder (here dir_, which has no content/) finds
// the source tree's config, before any install's.
TEST_F(DefaultEngineConfig, TheBuildTreeFindsTheSourceConfigFromAnyFolder) {
    const auto sourceContent = engine::buildTreeDataDir();
    ASSERT_TRUE(sourceContent) << "these tests run libengine from its build tree";
    const std::vector<fs::path> candidates = engine::defaultEngineConfigCandidates();
    ASSERT_EQ(candidates.size(), 3u);
    EXPECT_EQ(candidates[0], fs::path("content/engine.json"));
    EXPECT_EQ(candidates[1], *sourceContent / "engine.json");
    EXPECT_EQ(candidates[2], engine::installedDataDir() / "engine.json");
    EXPECT_EQ(engine::findDefaultEngineConfig(), *sourceContent / "engine.json");
}

TEST_F(DefaultEngineConfig, NoneFoundListsEveryPathTried) {
    const std::vector<fs::path> candidates = {dir_ / "content" / "engine.json", dir_ / "share" / "engine.json"};
    std::string message;
    try {
        engine::firstExistingEngineConfig(candidates);
    } catch (const engine::InputError& error) {
        message = error.what();
    }
    for (const fs::path& candidate : candidates)
        EXPECT_NE(message.find(candidate.string()), std::string::npos) << message;
}

} // namespace
