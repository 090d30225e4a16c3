#pragma once
// One headless GL context for the whole test process, created on first use.
//
//   class MyGlTest : public engine::test::GlTest {};   // current context + no-error check
//   TEST_F(MyGlTest, Draws) { ... }
//
// Tests that make another context current (e.g. a compatibility context) need do nothing
// special: GlTest::SetUp makes the shared context current again before each test.
#include "engine/context/GlContext.h"
#include "engine/gl/GlError.h"

#include <gtest/gtest.h>

#include <memory>

namespace engine::test {

// A debug context, so driver errors are printed where they happen (DebugOutput.h).
inline GlContext& glTestContext() {
    static const std::unique_ptr<GlContext> context = [] {
        ContextOptions options;
        options.debug = true;
        options.width = 64;
        options.height = 64;
        return createEglContext(options);
    }();
    context->makeCurrent();
    return *context;
}

class GlTest : public ::testing::Test {
protected:
    void SetUp() override { glTestContext(); }
    // Every GL test also checks that it left no GL error (as MAGNUM_VERIFY_NO_GL_ERROR);
    // checking drains the flags, so the next test starts clean either way.
    void TearDown() override {
        glTestContext(); // a test may have left another context current
        EXPECT_NO_THROW(gl::checkGlError("end of test"));
    }
};

} // namespace engine::test
