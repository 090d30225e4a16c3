// Plugins that load fine but fail while rendering a frame: each failure is one error naming
// the plugin or the pass at fault, typed as the plugin's fault, not the user's input.
#include "../gl/GlTestContext.h"

#include "engine/gl/GlError.h"
#include "engine/plugin/PluginHost.h"
#include "engine/render/Renderer.h"
#include "engine/scene/Scene.h"

#include <memory>

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
        FAIL() << "a pass reading another graph's texture rendered";
    } catch (const engine::InputError& error) {
        FAIL() << "the plugin's own mistake was reported as bad input: " << error.what();
    } catch (const engine::PluginError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("plugin \"bad_pass\""), std::string::npos) << message;
        EXPECT_NE(message.find("reads_nothing_real"), std::string::npos) << message;
        EXPECT_NE(message.find("of another graph"), std::string::npos) << message;
    }
}

// An empty scene rendered with the gl_error fixture plugin loaded.
struct GlErrorFixture {
    engine::PluginHost host;
    engine::Scene scene;
    std::unique_ptr<engine::Renderer> renderer;
    explicit GlErrorFixture(bool checkGlErrors) {
        host.load({"gl_error_plugin", {}}, {TEST_PLUGIN_DIR});
        engine::RendererConfig config;
        config.checkGlErrors = checkGlErrors;
        renderer = std::make_unique<engine::Renderer>(config, host.renderPlugins());
        renderer->setScene(scene);
    }
};

TEST_F(PluginFrameErrors, GlErrorIsReportedWithThePassThatRaisedIt) {
    GlErrorFixture fixture(true);  // what Debug builds default to
    try {
        fixture.renderer->renderFrame(tinyFrame());
        FAIL() << "an invalid glEnable went unreported";
    } catch (const engine::gl::GlError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("GL_INVALID_ENUM"), std::string::npos) << message;
        EXPECT_NE(message.find("pass \"enables_no_such_capability\""), std::string::npos) << message;
    }
}

TEST_F(PluginFrameErrors, GlErrorsAreNotCheckedWhenTheConfigSaysNot) {
    GlErrorFixture fixture(false);  // the Release default: no glGetError round trip per pass
    EXPECT_NO_THROW(fixture.renderer->renderFrame(tinyFrame()));
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM)) << "the flag the pass raised is still pending";
}
