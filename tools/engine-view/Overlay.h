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
