// What the plugin publishes in ShadowView::settings (printUsedSettings) reads back through
// the settings API (usedSettings) to the settings it rendered with, the polygon offset it
// used included, so tools never need the plugin's JSON keys or default rules.
#include "shadowmap/ShadowViewSettings.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

namespace {

using shadowmap::ShadowSettings;

engine::ShadowView publishedView(const ShadowSettings& settings) {
    engine::ShadowView view;
    view.name = "sun";
    view.settings = shadowmap::printUsedSettings(settings);
    return view;
}

// `settings` as the view gives it back: the offset made explicit, everything else as is.
ShadowSettings withUsedOffset(ShadowSettings settings) {
    settings.polygonOffset = settings.effectivePolygonOffset();
    return settings;
}

} // namespace

TEST(ShadowViewSettings, DefaultOffsetsReadBackAsTheOnesUsed) {
    using shadowmap::Filter, shadowmap::Variant, shadowmap::DepthFormat;
    for (Variant variant : {Variant::Standard, Variant::Woo, Variant::Backface, Variant::None})
        for (Filter filter : {Filter::Nearest, Filter::Pcf})
            for (bool reversedZ : {false, true}) {
                ShadowSettings settings;
                settings.variant = variant;
                settings.filter = filter;
                settings.reversedZ = reversedZ;
                if (reversedZ) settings.depthFormat = DepthFormat::D32F;
                const engine::ShadowView view = publishedView(settings);
                const ShadowSettings used = shadowmap::usedSettings(view);
                EXPECT_EQ(used, withUsedOffset(settings)) << view.settings.dump();
                EXPECT_EQ(used.effectivePolygonOffset(), settings.effectivePolygonOffset()) << view.settings.dump();
                EXPECT_EQ(shadowmap::usedVariant(view), variant);
            }
}

TEST(ShadowViewSettings, EveryOtherKeyReadsBackAsSet) {
    ShadowSettings settings;
    settings.variant = shadowmap::Variant::Woo;
    settings.resolution = 777;
    settings.depthFormat = shadowmap::DepthFormat::D16;
    settings.polygonOffset = glm::vec2(1.1f, 4.3f);  // explicit: kept as is
    settings.dimming = 0.73f;
    settings.nearPlane = 0.1;
    settings.farPlane = std::numeric_limits<double>::infinity();
    settings.polygonOffsetClamp = 2.7f;
    settings.cascades = 3;
    settings.cascadeLambda = 0.3;
    settings.cascadeBlend = 0.25;
    settings.stable = false;
    EXPECT_EQ(shadowmap::usedSettings(publishedView(settings)), settings);
}

TEST(ShadowViewSettings, ABadViewIsAnErrorNamingItsLight) {
    engine::ShadowView view;
    view.name = "sun";
    view.settings = {{"variant", "sharp"}};
    try {
        shadowmap::usedSettings(view);
        FAIL() << "no error";
    } catch (const std::exception& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("light \"sun\""), std::string::npos) << message;
        EXPECT_NE(message.find("variant"), std::string::npos) << message;
    }
}
