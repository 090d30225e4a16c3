// engine-view: a window on the same engine, config and plugin as engine-render, to choose
// each light's shadow settings by looking (live variant switching, the debug views of
// Kilgard's GDC 2000 slides, an on-screen line per light), scriptable (--script) and saving
// the choice back into the glTF (--save-settings).
#include "ToolMain.h"
#include "AutoExposure.h"
#include "Controls.h"
#include "DebugViews.h"
#include "OrbitCamera.h"
#include "Overlay.h"
#include "OverlayText.h"
#include "Playback.h"
#include "Presenter.h"
#include "SaveSettings.h"
#include "Script.h"
#include "ViewOptions.h"
#include "ViewerState.h"

#include "LightOverrides.h"
#include "SceneLighting.h"
#include "ShadowPluginConfig.h"

#include "engine/config/EngineConfig.h"
#include "engine/context/GlContext.h"
#include "engine/gltf/GltfLoader.h"
#include "engine/plugin/PluginHost.h"
#include "engine/render/Renderer.h"
#include "engine/scene/SceneNames.h"
#include "engine/util/Error.h"
#include "engine/util/ProcessSetup.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

namespace engine_view {
namespace {

// `fileLights`: how many glTF lights the file has; a --key-light added after them is the
// viewer's, not the file's, and is not saved.
void saveSettings(const ViewOptions& options, const ViewerState& state, const std::string& path, int fileLights) {
    std::map<int, nlohmann::json> shadows;
    for (std::size_t i = 0; i < state.lights().size(); ++i)
        if (state.lights()[i].light < fileLights)
            shadows[state.lights()[i].light] = state.savedShadow(static_cast<int>(i));
    tools::saveSceneSettings(options.scene, path, shadows);
}

// --light-set / --light: resolved to the scene's lights like engine-render's (a name, else a
// number from --list; a shared name sets every instance) and kept where the viewer keeps
// every edit (the light's extras.shadow), so the keys change them further and S saves them.
// Each is checked by the plugin now, so a bad one is an error naming it before the loop.
// A light's intensity and color go to the scene's light (the lit pass reads them each frame);
// they are this session's, not shadow settings, so S does not save them.
void applyLightOptions(const ViewOptions& options, engine::Scene& scene, ViewerState& state,
                       engine::Renderer& renderer) {
    const std::vector<tools::LightOverride> resolved =
        tools::resolveLightOverrides(options.lightSettings, [&](const std::string& light) {
            const int slot = engine::findLightInstanceByNameOrNumber(scene, light);
            if (slot < 0 || state.find(engine::lightInstanceName(scene, slot)) < 0)
                engine::throwInputError(options.scene, "light \"" + light + "\"",
                                        "no such light (" + engine::describeLightInstances(scene) + ")");
            return engine::lightInstanceName(scene, slot);
        });
    std::vector<std::string> warnings;
    const std::vector<tools::LightOverride> shadowSettings = tools::applyLightProperties(scene, resolved, warnings);
    for (const std::string& warning : warnings) std::cerr << "warning: " << warning << "\n";
    for (const tools::LightOverride& option : shadowSettings) {
        for (std::size_t i = 0; i < state.lights().size(); ++i)
            if (state.lights()[i].name == option.light) state.set(static_cast<int>(i), option.key, option.value);
        try {
            state.apply(renderer);
        } catch (const engine::InputError& error) {
            throw engine::InputError(option.text + ": " + error.what());
        }
    }
}

// A scripted run advances a playing clock by this per frame, whatever the machine's speed.
constexpr double kScriptedFrameSeconds = 1.0 / 30.0;

// --time and --animate: every animation is chosen (Space plays them), or the one --animate
// names; the scene is posed at --time (or 0 with --animate), else left at rest.
Playback startPlayback(const ViewOptions& options, engine::Scene& scene) {
    tools::AnimationPlayback choice;
    choice.animations = tools::selectAnimations(scene, options.scene, "--animate",
                                                options.animate.empty() ? "all" : options.animate);
    choice.startSeconds = options.time.value_or(0.0);
    Playback playback(scene, choice);
    if (options.time || !options.animate.empty()) playback.seek(choice.startSeconds);
    playback.setPlaying(!options.animate.empty());
    return playback;
}

// `context` and `host` live in main(), outside the try block that reports errors: an
// exception thrown by plugin code must be read before the plugin is unloaded, and the
// plugin's GL objects must be deleted while the context still exists (host first).
int run(const ViewOptions& options, std::unique_ptr<engine::GlContext>& context, engine::PluginHost& host) {
    engine::tuneAllocatorForRendering();
    const engine::EngineConfig config = engine::loadEngineConfig(options.config);
    std::optional<Script> script;
    if (!options.script.empty()) script = Script::load(options.script);  // bad lines fail before a window opens
    std::vector<std::string> warnings;
    engine::Scene scene = engine::loadGltf(options.scene, &warnings);
    for (const std::string& warning : warnings) std::cerr << "warning: " << warning << "\n";
    // Before a window opens: a save that cannot succeed is found now, not after the tuning.
    if (!options.saveSettings.empty()) tools::checkSaveTarget(options.scene, options.saveSettings);
    if (script) script->checkOutputs(options.scene, options.saveSettings);
    const int fileLights = static_cast<int>(scene.lights.size());
    const tools::StagedScene staged = tools::stageScene(scene, options.scene, options.lighting);
    for (const std::string& note : staged.notes) std::printf("engine-view: %s\n", note.c_str());
    for (const std::string& warning : staged.warnings) std::cerr << "warning: " << warning << "\n";

    engine::ContextOptions contextOptions;
    contextOptions.width = options.width;
    contextOptions.height = options.height;
    contextOptions.title = "engine-view: " + options.scene;
    context = engine::createGlfwContext(contextOptions);
    // GlContext does not expose its window; GLFW knows it as the current context.
    GLFWwindow* window = glfwGetCurrentContext();
    host.loadAll(config);
    engine::RendererConfig rendererConfig = config.renderer;
    if (options.exposureEv100) rendererConfig.exposure = engine::exposureFromEv100(*options.exposureEv100);
    auto ownedRenderer = std::make_unique<engine::Renderer>(rendererConfig, host.renderPlugins());
    ownedRenderer->setScene(scene);
    std::printf("engine-view: %s on %s\n", options.scene.c_str(), context->rendererString().c_str());

    ViewerState state(scene, tools::shadowPluginSettings(config));
    applyLightOptions(options, scene, state, *ownedRenderer);
    OrbitCamera camera(scene, options.scene, options.camera);
    Playback playback = startPlayback(options, scene);
    // --exposure auto: metered on the first frame as it will be shown (lights, settings, pose
    // and camera as set above), then kept: orbiting, switching lights or views never changes
    // the brightness behind the author's back (no flicker, no adaptation lag).
    if (options.autoExposure) {
        const glm::ivec2 size = context->framebufferSize();
        const tools::AutoExposure chosen = tools::chooseAutoExposure(
            rendererConfig, host.renderPlugins(), scene, camera.frameCamera(std::max(size.x, 1), std::max(size.y, 1)));
        std::printf("engine-view: %s\n", tools::describe(chosen).c_str());
        rendererConfig.exposure = chosen.exposure;
        ownedRenderer = std::make_unique<engine::Renderer>(rendererConfig, host.renderPlugins());
        ownedRenderer->setScene(scene);
    }
    engine::Renderer& renderer = *ownedRenderer;
    LoopRequests requests;
    Controls controls(state, camera, playback, requests);
    controls.attach(window);
    DebugViews views(renderer, scene);
    Presenter presenter;
    Overlay overlay;
    OverlayText overlayText;
    ViewFrame shown;
    bool exitAfterScreenshot = false;

    // A script's failure names its line; interactively, errors become the status line.
    const auto report = [&](const engine::InputError& error) {
        if (script) throw engine::InputError(script->where() + ": " + error.what());
        std::cerr << "engine-view: " << error.what() << "\n";
        requests.say(error.what(), true);
    };

    auto lastFrame = std::chrono::steady_clock::now();
    while (!requests.quit && !context->shouldClose()) {
        // A playing clock: wall-clock time between frames, or 1/30 s per scripted frame.
        const auto now = std::chrono::steady_clock::now();
        const double elapsed = script ? kScriptedFrameSeconds : std::chrono::duration<double>(now - lastFrame).count();
        lastFrame = now;
        if (playback.advance(elapsed)) requests.redraw = true;
        const glm::ivec2 size = context->framebufferSize();
        if (size.x > 0 && size.y > 0 && requests.redraw) {
            requests.redraw = false;
            try {
                state.apply(renderer);  // the plugin checks the edited settings here
            } catch (const engine::InputError& error) {
                report(error);
            }
            const int index = state.selected();
            shown = views.render(state.view(), index >= 0 ? &state.lights()[index] : nullptr,
                                 index >= 0 ? state.frameView(index) : nullptr, camera.frameCamera(size.x, size.y));
            state.setFrameViews(shown.frame.shadowViews);
            overlayText.recordFrame(shown.frame, state);
            presenter.present(shown.image, size.x, size.y);
            if (requests.overlay)
                overlay.draw(overlayText.lines(state, shown.frame, shown.notes, camera.describe(), playback.describe(),
                                               requests.status, requests.statusIsError),
                             size.x, size.y);
            if (!requests.screenshot.empty()) {
                presenter.screenshot(requests.screenshot, size.x, size.y);
                std::printf("engine-view: screenshot %s (%dx%d, view %s)\n", requests.screenshot.c_str(), size.x,
                            size.y, viewName(state.view()));
                requests.screenshot.clear();
                if (exitAfterScreenshot) requests.quit = true;
            }
            context->swapBuffers();
        }
        if (requests.save) {
            requests.save = false;
            const std::string path = requests.savePath.empty() ? options.saveSettings : requests.savePath;
            requests.savePath.clear();
            try {
                if (path.empty()) throw engine::InputError("S: nowhere to save: start with --save-settings FILE.gltf");
                saveSettings(options, state, path, fileLights);
                std::printf("engine-view: saved the lights' settings to %s\n", path.c_str());
                requests.say("saved the lights' settings to " + path);
            } catch (const engine::InputError& error) {
                report(error);
            }
        }
        if (requests.resizeWidth > 0) {
            glfwSetWindowSize(window, requests.resizeWidth, requests.resizeHeight);
            requests.resizeWidth = requests.resizeHeight = 0;
            requests.redraw = true;
        }
        if (requests.quit) break;
        // A finished script quits once its last frame is shown (and its screenshot taken):
        // under Xvfb nobody would ever close the window. --stay keeps it open for a person.
        if (script && script->finished() && !options.stay && options.screenshot.empty() && !requests.redraw) break;

        const bool scripted = script && !script->finished();
        if (scripted || requests.redraw || exitAfterScreenshot) context->pollEvents();
        else glfwWaitEventsTimeout(0.5);  // idle: nothing changes until an event comes
        if (scripted) {
            script->step(controls, state, camera, requests, size.y);
        } else if (!options.screenshot.empty() && !exitAfterScreenshot) {
            requests.screenshot = options.screenshot;  // the first frame after the script
            requests.redraw = exitAfterScreenshot = true;
        }
    }
    return 0;
}

} // namespace
} // namespace engine_view

int main(int argc, char** argv) {
    std::setvbuf(stdout, nullptr, _IOLBF, 0);  // progress lines show up at once, even piped
    return tools::toolMain("engine-view", engine_view::kViewUsage, argc, argv, engine_view::parseViewOptions,
                           [](const auto& options, tools::ToolSession& session) {
                               return engine_view::run(options, session.context, session.host);
                           });
}
