// ShaderLog is pure text: these tests need no context.
#include "engine/gl/ShaderLog.h"

#include <gtest/gtest.h>

namespace engine::gl {
namespace {

TEST(ShaderLogTest, FindsTheLineInEachDriversFormat) {
    const auto diagnostics = parseShaderLog("0:12(7): error: `x' undeclared\n"
                                            "0(3) : error C1008: undefined variable \"y\"\n"
                                            "ERROR: 0:44: 'z' : undeclared identifier\n"
                                            "compilation terminated.\n");
    ASSERT_EQ(diagnostics.size(), 4u);
    EXPECT_EQ(diagnostics[0].line, 12);
    EXPECT_EQ(diagnostics[1].line, 3);
    EXPECT_EQ(diagnostics[2].line, 44);
    EXPECT_EQ(diagnostics[3].line, 0);
    EXPECT_EQ(diagnostics[3].text, "compilation terminated.");
}

TEST(ShaderLogTest, AnnotationQuotesTheLineUnderEachDiagnostic) {
    const std::string source = "#version 450\nvoid main() {\n    bad;\n}\n";
    const std::string report = annotateShaderLog(
        "0:3(5): error: `bad' undeclared\n0:3(5): warning: statement has no effect\n", source);
    EXPECT_EQ(report, "0:3(5): error: `bad' undeclared\n"
                      "      3 |     bad;\n"
                      "0:3(5): warning: statement has no effect\n"
                      "      3 |     bad;\n");
}

TEST(ShaderLogTest, LinesOutsideTheSourceAreNotQuoted) {
    EXPECT_EQ(annotateShaderLog("0:99(1): error: nope", "void main() {}\n"),
              "0:99(1): error: nope\n");
}

} // namespace
} // namespace engine::gl
