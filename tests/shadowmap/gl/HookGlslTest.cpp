// The hook's GLSL is generated once per map layout and known by a version: the lit pass
// keys its programs by that version and never re-reads the text.
#include "plugin/HookGlsl.h"
#include "technique/Techniques.h"

#include <gtest/gtest.h>

#include <stdexcept>

using shadowmap::HookGlsl;

namespace {

// A shadowed light's lookup through the given filter's MapLookup.
HookGlsl::Lookup lookup(int slot, int unit, bool cube, int rawUnit, shadowmap::Filter filter = shadowmap::Filter::Pcf) {
    return {slot, unit, cube, rawUnit, 0, shadowmap::mapLookup(filter).glslName()};
}

std::size_t occurrences(const std::string& text, const std::string& part) {
    std::size_t count = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
    return count;
}

} // namespace

TEST(HookGlsl, OneLayoutOneVersionAndItsOldVersionWhenItReturns) {
    HookGlsl glsl;
    const std::vector<HookGlsl::Lookup> spotAndPoint{lookup(0, 4, false, 20), lookup(2, 6, true, 22)};
    const std::vector<HookGlsl::Lookup> spotOnly{lookup(0, 4, false, 20)};
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
    const HookGlsl::Code& code = glsl.codeFor({lookup(1, 5, false, -1), lookup(3, 7, true, 23)});
    EXPECT_NE(code.fragment.find("uniform sampler2DShadow uShadowMap1"), std::string::npos);
    EXPECT_NE(code.fragment.find("layout(binding = 7) uniform samplerCubeShadow uShadowMap3"), std::string::npos);
    EXPECT_EQ(code.fragment.find("uShadowDepth1"), std::string::npos) << "light 1 has no raw-depth unit";
    EXPECT_NE(code.fragment.find("uShadowDepth3"), std::string::npos);
    EXPECT_EQ(code.fragment.find("uShadowMap0"), std::string::npos) << "light 0 is not shadowed";
    EXPECT_NE(code.vertex.find("vShadowToPoint3 = shadowToPoint(3, eyePosition)"), std::string::npos);
    // Both stages read the same block: it leads each part.
    EXPECT_EQ(code.fragment.find("uniform ShadowData"), code.vertex.find("uniform ShadowData"));
}

// Each lookup's GLSL and the map shapes' functions written for it come once per GLSL name in
// use, whatever number of lights use it: nearest and pcf differ only in the sampler's filter,
// so they share one name, one copy and one program.
TEST(HookGlsl, EachLookupInUseIsWrittenOnceWithItsOwnGlsl) {
    HookGlsl glsl;
    const std::string name = shadowmap::mapLookup(shadowmap::Filter::Nearest).glslName();
    ASSERT_EQ(name, shadowmap::mapLookup(shadowmap::Filter::Pcf).glslName());
    const HookGlsl::Code& code = glsl.codeFor({lookup(0, 4, false, -1, shadowmap::Filter::Nearest),
                                               lookup(1, 5, false, -1), lookup(2, 6, true, -1)});
    EXPECT_EQ(occurrences(code.fragment, "float " + name + "2D("), 1u);
    EXPECT_EQ(occurrences(code.fragment, "float shadowMap2D_" + name + "("), 1u);
    EXPECT_EQ(occurrences(code.fragment, "return shadowMap2D_" + name + "("), 2u);  // lights 0 and 1
    EXPECT_EQ(occurrences(code.fragment, "return shadowMapCube_" + name + "("), 1u);
    EXPECT_EQ(code.fragment.find("$LOOKUP"), std::string::npos) << "a placeholder left in the GLSL";
    EXPECT_EQ(glsl.codeFor({lookup(0, 4, false, -1, shadowmap::Filter::Nearest), lookup(1, 5, false, -1),
                            lookup(2, 6, true, -1, shadowmap::Filter::Nearest)}).version,
              code.version) << "a filter change that keeps the GLSL must keep the program";

    HookGlsl::Lookup unknown = lookup(0, 4, false, -1);
    unknown.glslName = "noSuchLookup";
    try {
        (void)glsl.codeFor({unknown});
        ADD_FAILURE() << "an unknown lookup name was accepted";
    } catch (const std::logic_error& error) {
        EXPECT_NE(std::string(error.what()).find("noSuchLookup"), std::string::npos) << error.what();
    }
}
