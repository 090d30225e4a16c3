// Plugins that load fine but fail while rendering a frame: each failure is one error naming
// the plugin or the pass at fault, typed as the plugin's fault, not the user's input.
#include "../gl/GlTestContext.h"

#include "engine/gl/GlError.h"
#include "engine/plugin/PluginHost.h"
#include "engine/render/Renderer.h"
#include "engine/scene/Scene.h"

namespace {

engine::FrameRequest tinyFrame() {
    engine::FrameRequest request;
    request.camera.width = request.camera.height = 8;
    return request;
}

} // namespace

class PluginFrameErrors : public engine::test::GlTest {};

TEST_F(PluginFrameErrors, BadPassDeclarationNamesPluginPassAndResource) {
    engine::PluginHost host;
    host.load({"bad_pass_plugin", {}}, {TEST_PLUGIN_DIR});
    engine::Scene scene;
    engine::Renderer renderer({}, host.renderPlugins());
    renderer.setScene(scene);
    try {
        renderer.renderFrame(tinyFrame());
        FAIL() << "a pass reading an undeclared texture rendered";
    } catch (const engine::InputError& error) {
        FAIL() << "the plugin's own mistake was reported as bad input: " << error.what();
    } catch (const engine::PluginError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("plugin \"bad_pass\""), std::string::npos) << message;
        EXPECT_NE(message.find("reads_nothing_real"), std::string::npos) << message;
        EXPECT_NE(message.find("texture_nobody_made"), std::string::npos) << message;
    }
}

TEST_F(PluginFrameErrors, GlErrorIsReportedWithThePassThatRaisedIt) {
    engine::PluginHost host;
    host.load({"gl_error_plugin", {}}, {TEST_PLUGIN_DIR});
    engine::Scene scene;
    engine::RendererConfig config;
    config.checkGlErrors = true;  // what Debug builds default to
    engine::Renderer renderer(config, host.renderPlugins());
    renderer.setScene(scene);
    try {
        renderer.renderFrame(tinyFrame());
        FAIL() << "an invalid glEnable went unreported";
    } catch (const engine::gl::GlError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("GL_INVALID_ENUM"), std::string::npos) << message;
        EXPECT_NE(message.find("pass \"enables_no_such_capability\""), std::string::npos) << message;
    }
}

TEST_F(PluginFrameErrors, GlErrorsAreNotCheckedWhenTheConfigSaysNot) {
    engine::PluginHost host;
    host.load({"gl_error_plugin", {}}, {TEST_PLUGIN_DIR});
    engine::Scene scene;
    engine::RendererConfig config;
    config.checkGlErrors = false;  // the Release default: no glGetError round trip per pass
    engine::Renderer renderer(config, host.renderPlugins());
    renderer.setScene(scene);
    EXPECT_NO_THROW(renderer.renderFrame(tinyFrame()));
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM)) << "the flag the pass raised is still pending";
}
