// The hook's GLSL is generated once per map layout and known by a version: the lit pass
// keys its programs by that version and never re-reads the text.
#include "plugin/HookGlsl.h"

#include <gtest/gtest.h>

using shadowmap::HookGlsl;

TEST(HookGlsl, OneLayoutOneVersionAndItsOldVersionWhenItReturns) {
    HookGlsl glsl;
    const std::vector<HookGlsl::Lookup> spotAndPoint{{0, 4, false, 20}, {2, 6, true, 22}};
    const std::vector<HookGlsl::Lookup> spotOnly{{0, 4, false, 20}};
    const HookGlsl::Code& first = glsl.codeFor(spotAndPoint);
    const std::uint64_t firstVersion = first.version;
    EXPECT_NE(firstVersion, 0u) << "0 means 'no version' to the lit pass";
    EXPECT_EQ(&glsl.codeFor(spotAndPoint), &first) << "the same layout generated its code again";

    const std::uint64_t spotVersion = glsl.codeFor(spotOnly).version;
    EXPECT_NE(spotVersion, firstVersion);
    EXPECT_EQ(glsl.codeFor(spotAndPoint).version, firstVersion) << "a returning layout must keep its version";
    EXPECT_EQ(glsl.layouts(), 2u);
}

TEST(HookGlsl, TheCodeHasALookupPerShadowedLightAndNoneForOthers) {
    HookGlsl glsl;
    const HookGlsl::Code& code = glsl.codeFor({{1, 5, false, -1}, {3, 7, true, 23}});
    EXPECT_NE(code.fragment.find("uniform sampler2DShadow uShadowMap1"), std::string::npos);
    EXPECT_NE(code.fragment.find("layout(binding = 7) uniform samplerCubeShadow uShadowMap3"), std::string::npos);
    EXPECT_EQ(code.fragment.find("uShadowDepth1"), std::string::npos) << "light 1 has no raw-depth unit";
    EXPECT_NE(code.fragment.find("uShadowDepth3"), std::string::npos);
    EXPECT_EQ(code.fragment.find("uShadowMap0"), std::string::npos) << "light 0 is not shadowed";
    EXPECT_NE(code.vertex.find("vShadowToPoint3 = shadowToPoint(3, eyePosition)"), std::string::npos);
    // Both stages read the same block: it leads each part.
    EXPECT_EQ(code.fragment.find("uniform ShadowData"), code.vertex.find("uniform ShadowData"));
}
