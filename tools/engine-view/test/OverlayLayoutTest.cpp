// engine-view's overlay laid out without a window (layoutOverlay, Overlay.h): every row it
// draws fits the window's width, measured in the overlay's font units as stb_easy_font draws
// them, for the showcase's light lines as long as they get.
#include "Overlay.h"
#include "OverlayText.h"
#include "ViewerState.h"

#include "engine/gltf/GltfLoader.h"

#include "shadowmap/ShadowSettings.h"
#include "shadowmap/ShadowViewSettings.h"

#include <gtest/gtest.h>
#include <stb/stb_easy_font.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace engine_view {
namespace {

// The overlay of the showcase's three lights as the viewer shows them, each line as long as
// it gets: the sun soft (angular_diameter 0.0093 rad, the real sun's; pcss) with a fractional
// polygon offset, the spot with its map rendered this frame in 1234.56 ms, the point light
// with no map and the longest reason the plugin gives (no receiver in its frustum), a
// four-digit frame time, and a status message longer than a narrow window is wide.
std::vector<OverlayLine> showcaseOverlay(engine::Scene& scene) {
    const nlohmann::json defaults = {{"variant", "standard"}, {"resolution", 2048}, {"depth_format", "d24"},
                                     {"filter", "pcf"}};  // content/engine.json's
    for (engine::Light& light : scene.lights)
        if (light.name == "sun")
            light.extras["shadow"].update({{"angular_diameter", 0.0093}, {"filter", "pcss"},
                                           {"polygon_offset", {1.25, 12.5}}, {"dimming", 0.35}});
    ViewerState state(scene, defaults);
    engine::FrameResult frame;
    frame.frameMs = 1234.5;
    std::vector<engine::ShadowView> views;
    for (std::size_t i = 0; i < state.lights().size(); ++i) {
        const ViewedLight& light = state.lights()[i];
        engine::ShadowView view;
        view.slot = light.slot;
        view.name = light.name;
        view.castsShadows = true;
        view.hasMap = light.type != engine::Light::Type::Point;
        if (!view.hasMap) view.skipReason = "no visible receiver in the light's frustum";
        view.cube = light.type == engine::Light::Type::Point;
        view.settings = shadowmap::printUsedSettings(
            shadowmap::parseSettings(state.effective(static_cast<int>(i)), "showcase.gltf", light.name));
        engine::PassReport pass;
        pass.wallMs = 1234.56;
        view.passes = {engine::PassId{static_cast<int>(frame.passes.size())}};
        frame.passes.push_back(pass);
        frame.shadeCache.computed.push_back(light.slot);
        views.push_back(view);
    }
    state.setFrameViews(views);
    OverlayText text;
    text.recordFrame(frame, state);
    return text.lines(state, frame, {"penumbra: tinted where the light is partly seen"}, "main_camera (glTF camera 1)",
                      "animation: none", "saved the lights' settings to /home/someone/projects/scenes/showcase_tuned.gltf",
                      false);
}

// The overlay's line of `name` in `lines`.
std::string lineOf(const std::vector<OverlayLine>& lines, const std::string& name) {
    for (const OverlayLine& line : lines)
        if (line.text.find(name + "\t") != std::string::npos) return line.text;
    return {};
}

// The right edge, in window pixels, of what stb_easy_font draws for `text` at font-unit x.
float drawnRight(const std::string& text, float x, float scale) {
    std::string copy = text;
    std::vector<char> buffer(copy.size() * 70 * 16 + 64);
    unsigned char color[4] = {255, 255, 255, 255};
    const int quads = stb_easy_font_print(x, 0.0f, copy.data(), color, buffer.data(), static_cast<int>(buffer.size()));
    float right = x;
    for (int q = 0; q < 4 * quads; ++q) {
        float vertexX = 0.0f;
        std::memcpy(&vertexX, buffer.data() + 16 * q, sizeof vertexX);  // x, y, z floats, 4 colour bytes
        right = std::max(right, vertexX);
    }
    return right * scale;
}

std::string withoutSpaces(std::string text) {
    text.erase(std::remove_if(text.begin(), text.end(), [](char c) { return c == ' ' || c == '\t'; }), text.end());
    return text;
}

} // namespace

// Every row the overlay draws, text and band, ends inside the window, at the default
// 1280 x 720, a 640-pixel window (2x text from 480 tall, 1x below) and a wide one; wrapping
// loses no character and keeps each row with its line, and a window wide enough for the
// lines wraps none.
TEST(ViewerOverlay, EveryRowFitsTheWindowsWidth) {
    engine::Scene scene = engine::loadGltf(std::filesystem::path(CONTENT_DIR) / "scenes" / "showcase.gltf");
    const std::vector<OverlayLine> lines = showcaseOverlay(scene);
    ASSERT_GE(lines.size(), 8u);
    for (const glm::ivec2 window : {glm::ivec2(1280, 720), glm::ivec2(640, 480), glm::ivec2(640, 360),
                                    glm::ivec2(320, 240), glm::ivec2(3840, 2160)}) {
        SCOPED_TRACE(std::to_string(window.x) + "x" + std::to_string(window.y));
        const OverlayLayout layout = layoutOverlay(lines, window.x, window.y);
        EXPECT_EQ(layout.scale, window.y >= 480 ? 2.0f : 1.0f);
        std::vector<std::string> shown(lines.size());
        int lastLine = 0;
        for (const OverlayRow& row : layout.rows) {
            EXPECT_LE(row.right * layout.scale, static_cast<float>(window.x)) << lines[row.line].text;
            EXPECT_GE(row.line, lastLine);  // rows in line order
            lastLine = row.line;
            EXPECT_EQ(row.color, lines[row.line].color);
            for (const OverlayCell& cell : row.cells) {
                EXPECT_LE(drawnRight(cell.text, cell.x, layout.scale), static_cast<float>(window.x)) << cell.text;
                EXPECT_LE(drawnRight(cell.text, cell.x, 1.0f), row.right) << "the band covers " << cell.text;
                shown[row.line] += cell.text;
            }
        }
        for (std::size_t i = 0; i < lines.size(); ++i) EXPECT_EQ(withoutSpaces(shown[i]), withoutSpaces(lines[i].text));
        if (window.x >= 3840) {
            EXPECT_EQ(layout.rows.size(), lines.size()) << "nothing wraps in a wide window";
        }
        if (static_cast<float>(window.x) / layout.scale <= 320.0f) {
            EXPECT_GT(layout.rows.size(), lines.size()) << "a window 320 font units wide wraps";
        }
    }
}

// The sun's line as the viewer drew it before lines wrapped (one row, columns aligned) is
// wider than the default 1280-pixel window: the case the layout must wrap.
TEST(ViewerOverlay, TheSunsLineIsWiderThanTheDefaultWindowUnwrapped) {
    engine::Scene scene = engine::loadGltf(std::filesystem::path(CONTENT_DIR) / "scenes" / "showcase.gltf");
    const std::vector<OverlayLine> lines = showcaseOverlay(scene);
    const OverlayLayout unwrapped = layoutOverlay(lines, 1 << 20, 720);  // wide enough for any line
    ASSERT_EQ(unwrapped.rows.size(), lines.size());
    const auto sun = std::find_if(unwrapped.rows.begin(), unwrapped.rows.end(), [&](const OverlayRow& row) {
        return lines[row.line].text.find("sun\t") != std::string::npos;
    });
    ASSERT_NE(sun, unwrapped.rows.end());
    EXPECT_GT(sun->right * unwrapped.scale, 1280.0f);
    const OverlayLayout wrapped = layoutOverlay(lines, 1280, 720);
    EXPECT_GT(std::count_if(wrapped.rows.begin(), wrapped.rows.end(), [&](const OverlayRow& row) { return row.line == sun->line; }),
              1);
}

// Columns still line up: the lights' cells start where their column starts, on the rows
// that are not wrapped.
TEST(ViewerOverlay, LightLinesKeepTheirColumnsWhereTheyFit) {
    const std::vector<OverlayLine> lines = {{"a\tbb\tc"}, {"dddd\te\tf"}};
    const OverlayLayout layout = layoutOverlay(lines, 1280, 720);
    ASSERT_EQ(layout.rows.size(), 2u);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(layout.rows[0].cells[c].x, layout.rows[1].cells[c].x) << c;
    EXPECT_GT(layout.rows[0].cells[1].x, overlayTextWidth("dddd") + layout.rows[0].cells[0].x);
}

// A volume light has no map but is shadowed: its line gives its passes' time, rendered or
// cached as a map's, says "per pixel" and "hard" where a map's size and filter stand, and
// never "no map" as an unshadowed light's does.
TEST(ViewerOverlay, AVolumeLightShowsItsTimeNotNoMap) {
    engine::Scene scene = engine::loadGltf(std::filesystem::path(CONTENT_DIR) / "scenes" / "showcase.gltf");
    ViewerState state(scene, {{"variant", "standard"}, {"resolution", 2048}});
    ASSERT_TRUE(state.select("spot_light"));
    const int spot = state.selected();
    state.set(spot, "variant", "volume");
    for (const bool ran : {true, false}) {
        engine::FrameResult frame;
        std::vector<engine::ShadowView> views;
        for (std::size_t i = 0; i < state.lights().size(); ++i) {
            engine::ShadowView view;
            view.slot = state.lights()[i].slot;
            view.name = state.lights()[i].name;
            view.castsShadows = true;
            const bool volume = static_cast<int>(i) == spot;
            view.hasMap = !volume;
            view.hasScreenVisibility = volume;
            view.renderedThisFrame = ran;
            view.variant = volume ? "volume" : "standard";
            view.settings = shadowmap::printUsedSettings(
                shadowmap::parseSettings(state.effective(static_cast<int>(i)), "showcase.gltf", view.name));
            engine::PassReport pass;
            pass.wallMs = 2.5;
            pass.culled = !ran;
            view.passes = {engine::PassId{static_cast<int>(frame.passes.size())}};
            frame.passes.push_back(pass);
            views.push_back(view);
        }
        state.setFrameViews(views);
        frame.shadowViews = views;
        static OverlayText text;  // keeps the last time across the two frames, as the viewer does
        text.recordFrame(frame, state);
        const std::string line = lineOf(text.lines(state, frame, {}, "camera", "", "", false), "spot_light");
        SCOPED_TRACE(line);
        EXPECT_NE(line.find("\tvolume\tper pixel\t"), std::string::npos);
        EXPECT_NE(line.find("\thard\t"), std::string::npos);
        EXPECT_EQ(line.find("no map"), std::string::npos);
        EXPECT_EQ(line.find("offset"), std::string::npos);
        EXPECT_NE(line.find(ran ? "2.50 ms\trendered" : "2.50 ms\tcached"), std::string::npos);
    }
}

} // namespace engine_view
