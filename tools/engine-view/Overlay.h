#pragma once
// On-screen text: lines drawn top-left over the presented picture, each on a translucent
// dark band, with stb_easy_font's quads (scaled 2x once the window is 480 pixels tall) and
// a tiny GL program (positions in pixels, a colour per vertex, alpha blending).
#include "engine/gl/Buffer.h"
#include "engine/gl/Program.h"
#include "engine/gl/VertexArray.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace engine_view {

struct OverlayLine {
    std::string text;
    glm::u8vec4 color{235, 235, 235, 255};
};

// Where the overlay's text goes. Font units are stb_easy_font's (a glyph 7 high, about 6 wide);
// a window pixel is `scale` of them. Tab-separated cells line up in columns across lines; a
// line that would run past the window's right edge wraps at a cell boundary (a cell wider
// than the window at a space, else between characters) onto indented rows of its own.
struct OverlayCell {
    std::string text;
    float x = 0.0f;  // font units from the window's left edge
};
struct OverlayRow {
    int line = 0;  // the index of the line it shows (all or part of)
    std::vector<OverlayCell> cells;
    glm::u8vec4 color{235, 235, 235, 255};
    float right = 0.0f;  // the right edge of its band (the text's end and a margin), font units
};
struct OverlayLayout {
    float scale = 1.0f;            // window pixels per font unit: 2 once the window is 480 tall
    std::vector<OverlayRow> rows;  // top to bottom, one kOverlayRowHeight apart
};
constexpr float kOverlayRowHeight = 12.0f;  // font units (the glyphs are 7 high)
// The text's width as drawn, font units.
float overlayTextWidth(const std::string& text);
// Every row's band ends within the window: right * scale <= width (when the window is at
// least a few characters wide).
OverlayLayout layoutOverlay(const std::vector<OverlayLine>& lines, int width, int height);

class Overlay {
public:
    Overlay();  // compiles the program: a GL context must be current
    // Into the default framebuffer's back buffer, a window of `width` x `height` pixels.
    void draw(const std::vector<OverlayLine>& lines, int width, int height);

private:
    engine::gl::Program program_;
    engine::gl::VertexArray vertexArray_;
    engine::gl::Buffer vertices_;
};

} // namespace engine_view
