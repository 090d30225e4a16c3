// The smallest program on libengine: load an engine config (which names the plugins) and a
// glTF scene, render one frame headless, write it as PNG, and list the frame's passes.
//
//   render_one_frame CONFIG.json SCENE.gltf OUT.png
//
// Everything a tool needs is here; the real tools (tools/engine-render) add options,
// timing and reports around the same calls.
#include "engine/config/EngineConfig.h"
#include "engine/context/GlContext.h"
#include "engine/gltf/GltfLoader.h"
#include "engine/plugin/PluginHost.h"
#include "engine/render/CameraSetup.h"
#include "engine/render/Renderer.h"
#include "engine/util/Error.h"
#include "engine/util/OutputFile.h"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: %s CONFIG.json SCENE.gltf OUT.png\n", argv[0]);
        return 2;
    }
    // The context comes first and goes last: plugins delete GL objects when unloaded.
    const auto context = engine::createEglContext();  // surfaceless: no window, no display
    context->makeCurrent();
    engine::PluginHost host;
    try {
        const engine::EngineConfig config = engine::loadEngineConfig(argv[1]);
        host.loadAll(config);
        const engine::Scene scene = engine::loadGltf(argv[2]);

        engine::Renderer renderer(config.renderer, host.renderPlugins());
        renderer.setScene(scene);  // uploads the geometry; plugins read per-light settings
        engine::FrameRequest request;
        request.camera = engine::chooseCamera(scene, "", 320, 240, argv[2]);  // the first camera, else one framing the scene
        const engine::FrameResult frame = renderer.renderFrame(request);

        engine::writePngAtomically(argv[3], request.camera.width, request.camera.height, 4, renderer.readColor());
        for (const engine::PassReport& pass : frame.passes)
            std::printf("%-24s %s\n", pass.name.c_str(), pass.culled ? pass.cullReason.c_str() : "ran");
        for (const engine::ShadowView& view : frame.shadowViews)
            std::printf("light %-18s %s\n", view.name.c_str(), view.hasMap ? view.variant.c_str() : view.skipReason.c_str());
    } catch (const std::exception& error) {  // InputError: one line naming file, object, reason
        std::fprintf(stderr, "render_one_frame: %s\n", error.what());
        return 1;
    }
    return 0;
}
