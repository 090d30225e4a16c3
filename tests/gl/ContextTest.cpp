// The headless contexts: version and profile asked for, debug output, clear failures.
#include "GlTestContext.h"

#include <string>

namespace engine {
namespace {

using ContextTest = test::GlTest;

TEST_F(ContextTest, SharedContextIsOpenGl45Core) {
    const GlContext& context = test::glTestContext();
    GLint major = 0, minor = 0, profile = 0, flags = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    glGetIntegerv(GL_CONTEXT_FLAGS, &flags);
    EXPECT_EQ(major, 4);
    EXPECT_EQ(minor, 5);
    EXPECT_EQ(profile, GL_CONTEXT_CORE_PROFILE_BIT);
    EXPECT_TRUE(flags & GL_CONTEXT_FLAG_DEBUG_BIT);
    EXPECT_TRUE(flags & GL_CONTEXT_FLAG_FORWARD_COMPATIBLE_BIT);
    EXPECT_EQ(context.versionString().rfind("4.5", 0), 0u) << context.versionString();
    EXPECT_FALSE(context.rendererString().empty());
    EXPECT_EQ(context.framebufferSize(), glm::ivec2(64, 64));
    RecordProperty("renderer", context.rendererString());
}

TEST_F(ContextTest, DebugOutputPrintsErrorsToStderr) {
    testing::internal::CaptureStderr();
    glEnable(0xBAD); // not a capability: GL_INVALID_ENUM, reported at high severity
    const std::string printed = testing::internal::GetCapturedStderr();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
    EXPECT_NE(printed.find("GL debug"), std::string::npos) << printed;
    EXPECT_NE(printed.find("error"), std::string::npos) << printed;
}

// The texgen oracle (TexgenOracleTest) needs fixed-function glTexGen: a compatibility context.
// It lives beside the shared core context; GlTest makes the shared one current again.
TEST_F(ContextTest, CompatibilityContextHasFixedFunctionTexgen) {
    ContextOptions options;
    options.coreProfile = false;
    const std::unique_ptr<GlContext> compatibility = createEglContext(options);
    GLint major = 0, minor = 0, profile = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    // At least the 4.5 asked for: EGL may give a later version that is backward compatible
    // with it (llvmpipe gives 4.5, NVIDIA's driver 4.6).
    EXPECT_GE(major * 10 + minor, 45) << major << "." << minor;
    EXPECT_EQ(profile, GL_CONTEXT_COMPATIBILITY_PROFILE_BIT);

    const GLfloat plane[] = {1.0f, 2.0f, 3.0f, 4.0f};
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGenfv(GL_S, GL_EYE_PLANE, plane); // modelview is identity: stored unchanged
    GLfloat stored[4] = {};
    glGetTexGenfv(GL_S, GL_EYE_PLANE, stored);
    EXPECT_NO_THROW(gl::checkGlError("glTexGen in a compatibility context"));
    for (int i = 0; i < 4; ++i) EXPECT_EQ(stored[i], plane[i]);

    // Switching back and forth keeps each context's own profile.
    test::glTestContext();
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    EXPECT_EQ(profile, GL_CONTEXT_CORE_PROFILE_BIT);
    compatibility->makeCurrent();
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    EXPECT_EQ(profile, GL_CONTEXT_COMPATIBILITY_PROFILE_BIT);
}

TEST_F(ContextTest, ImpossibleVersionIsAClearError) {
    ContextOptions options;
    options.major = 9;
    options.minor = 9;
    try {
        createEglContext(options);
        FAIL() << "an OpenGL 9.9 context was created";
    } catch (const ContextError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("EGL"), std::string::npos) << message;
        EXPECT_NE(message.find("OpenGL 9.9 core"), std::string::npos) << message;
    }
}

} // namespace
} // namespace engine
