// Uses an installed engine as a user would: the default config and the shadow plugin are
// found by the engine itself (no paths given), the showcase scene beside the config. Renders
// one small frame headless with the config's plugins and one without, and checks that the
// plugin came from the install under test and that it darkened some pixels.
//
//   consumer INSTALL_PREFIX     (run from a folder without content/, ENGINE_PLUGIN_PATH unset)
#include "engine/config/EngineConfig.h"
#include "engine/context/GlContext.h"
#include "engine/gltf/GltfLoader.h"
#include "engine/plugin/PluginHost.h"
#include "engine/render/CameraSetup.h"
#include "engine/render/Renderer.h"

#include <shadowmap/ShadowSettings.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

bool isInside(const fs::path& file, const fs::path& folder) {
    const std::string f = fs::canonical(file).string(), d = fs::canonical(folder).string() + "/";
    return f.compare(0, d.size(), d) == 0;
}

std::vector<std::uint8_t> render(const engine::RendererConfig& config,
                                 std::vector<engine::RenderPlugin*> plugins, const engine::Scene& scene,
                                 const engine::FrameRequest& request, int* shadowMaps) {
    engine::Renderer renderer(config, std::move(plugins));
    renderer.setScene(scene);
    const engine::FrameResult frame = renderer.renderFrame(request);
    for (const engine::ShadowView& view : frame.shadowViews) {
        shadowmap::parseVariant(view.variant, "consumer", view.name);  // the settings API links
        if (view.hasMap) ++*shadowMaps;
    }
    return renderer.readColor();
}

int fail(const std::string& why) {
    std::fprintf(stderr, "consumer: FAIL: %s\n", why.c_str());
    return 1;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) return fail("usage: consumer INSTALL_PREFIX");
    const fs::path prefix = argv[1];
    const auto context = engine::createEglContext();
    context->makeCurrent();
    engine::PluginHost host;
    try {
        const fs::path configPath = engine::findDefaultEngineConfig();
        if (!isInside(configPath, prefix)) return fail("default config " + configPath.string() + " is not the installed one");
        const engine::EngineConfig config = engine::loadEngineConfig(configPath);
        host.loadAll(config);
        if (host.loadedFiles().size() != 1 || !isInside(host.loadedFiles()[0], prefix))
            return fail("the installed shadow plugin was not the one loaded");
        std::printf("config %s\nplugin %s\n", configPath.c_str(), host.loadedFiles()[0].c_str());

        const fs::path scenePath = configPath.parent_path() / "scenes" / "showcase.gltf";
        const engine::Scene scene = engine::loadGltf(scenePath);
        engine::FrameRequest request;
        // Small: the check needs shadowed pixels, not detail, and must stay fast under ASan.
        request.camera = engine::chooseCamera(scene, "", 160, 120, scenePath.string());
        int maps = 0, noMaps = 0;
        const auto shadowed = render(config.renderer, host.renderPlugins(), scene, request, &maps);
        const auto unshadowed = render(config.renderer, {}, scene, request, &noMaps);
        // A pixel counts as shadowed when the plugin made it darker by more than 8/255 in the
        // sum of R, G and B: two renders differing only in the shadow term differ by 8-bit
        // rounding (at most 1/255 per channel) elsewhere, and a shadow removes at least
        // (1 - dimming 0.4) of a light's diffuse part.
        std::size_t darker = 0;
        for (std::size_t i = 0; i + 3 < shadowed.size(); i += 4) {
            const int with = shadowed[i] + shadowed[i + 1] + shadowed[i + 2];
            const int without = unshadowed[i] + unshadowed[i + 1] + unshadowed[i + 2];
            if (without - with > 8) ++darker;
        }
        std::printf("shadow maps %d, shadowed pixels %zu of %zu\n", maps, darker, shadowed.size() / 4);
        if (maps == 0) return fail("the plugin rendered no shadow map");
        if (darker == 0) return fail("no pixel is shadowed");
    } catch (const std::exception& error) {
        return fail(error.what());
    }
    std::printf("consumer OK\n");
    return 0;
}
