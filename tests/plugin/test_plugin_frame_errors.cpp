// A plugin that loads fine but declares a bad pass: rendering a frame fails with one
// InputError naming the plugin, the pass and the resource.
#include "../gl/GlTestContext.h"

#include "engine/plugin/PluginHost.h"
#include "engine/render/Renderer.h"
#include "engine/scene/Scene.h"

class PluginFrameErrors : public engine::test::GlTest {};

TEST_F(PluginFrameErrors, BadPassDeclarationNamesPluginPassAndResource) {
    engine::PluginHost host;
    host.load({"bad_pass_plugin", {}}, {TEST_PLUGIN_DIR});
    engine::Scene scene;
    engine::Renderer renderer({}, host.renderPlugins());
    renderer.setScene(scene);
    engine::FrameRequest request;
    request.camera.width = request.camera.height = 8;
    try {
        renderer.renderFrame(request);
        FAIL() << "a pass reading an undeclared texture rendered";
    } catch (const engine::InputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("plugin \"bad_pass\""), std::string::npos) << message;
        EXPECT_NE(message.find("reads_nothing_real"), std::string::npos) << message;
        EXPECT_NE(message.find("texture_nobody_made"), std::string::npos) << message;
    }
}
