#include "Overlay.h"

#include <stb/stb_easy_font.h>

#include <algorithm>

namespace engine_view {

namespace {

const char* const kVertexShader = R"(#version 450 core
layout(location = 0) in vec2 aPosition;  // pixels, y down
layout(location = 1) in vec4 aColor;
uniform vec2 uViewport;
out vec4 vColor;
void main() {
    gl_Position = vec4(aPosition.x / uViewport.x * 2.0 - 1.0, 1.0 - aPosition.y / uViewport.y * 2.0, 0.0, 1.0);
    vColor = aColor;
}
)";

const char* const kFragmentShader = R"(#version 450 core
in vec4 vColor;
out vec4 fragColor;
void main() { fragColor = vColor; }
)";

struct Vertex {
    float x, y;
    glm::u8vec4 color;
};

// stb_easy_font's vertex: x, y, z floats and 4 colour bytes.
struct StbVertex {
    float x, y, z;
    unsigned char color[4];
};

void addQuad(std::vector<Vertex>& out, glm::vec2 a, glm::vec2 b, glm::u8vec4 color) {
    const Vertex corners[4] = {{a.x, a.y, color}, {b.x, a.y, color}, {b.x, b.y, color}, {a.x, b.y, color}};
    for (int index : {0, 1, 2, 0, 2, 3}) out.push_back(corners[index]);
}

} // namespace

Overlay::Overlay()
    : program_(engine::gl::Program::compile("engine-view overlay", {{GL_VERTEX_SHADER, kVertexShader},
                                                                      {GL_FRAGMENT_SHADER, kFragmentShader}})),
      vertexArray_(engine::gl::VertexArray::create()) {}

namespace {

std::vector<std::string> splitColumns(const std::string& text) {
    std::vector<std::string> columns(1);
    for (char c : text) {
        if (c == '\t') columns.emplace_back();
        else columns.back() += c;
    }
    return columns;
}

// Font units: where text starts, the band's margins around it, the space between columns,
// and how far a wrapped line's later rows are indented.
constexpr float kTextLeft = 4.0f, kBandLeft = 1.0f, kBandRight = 3.0f, kColumnGap = 9.0f, kWrapIndent = 12.0f;

// The longest start of `text` (at least one character) that fits in `room` font units: up to
// its last space that fits when one does, else as many characters as fit.
std::size_t fittingPrefix(const std::string& text, float room) {
    std::size_t chars = 1;
    while (chars < text.size() && overlayTextWidth(text.substr(0, chars + 1)) <= room) ++chars;
    if (chars == text.size()) return chars;
    const std::size_t space = text.rfind(' ', chars);
    return space != std::string::npos && space > 0 ? space + 1 : chars;
}

} // namespace

float overlayTextWidth(const std::string& text) {
    std::string copy = text;  // stb_easy_font wants a mutable char*
    return static_cast<float>(stb_easy_font_width(copy.data()));
}

OverlayLayout layoutOverlay(const std::vector<OverlayLine>& lines, int width, int height) {
    OverlayLayout layout;
    layout.scale = height >= 480 ? 2.0f : 1.0f;
    const float limit = static_cast<float>(width) / layout.scale - kBandRight;  // where text must end
    // Tab-separated columns line up across all lines: each starts after the widest cell of
    // the column before it (stb_easy_font is proportional, so spaces cannot align them).
    std::vector<std::vector<std::string>> cells;
    std::vector<float> columnWidth;
    for (const OverlayLine& line : lines) {
        cells.push_back(splitColumns(line.text));
        if (cells.back().size() < 2) continue;
        columnWidth.resize(std::max(columnWidth.size(), cells.back().size()), 0.0f);
        for (std::size_t c = 0; c < cells.back().size(); ++c)
            columnWidth[c] = std::max(columnWidth[c], overlayTextWidth(cells.back()[c]));
    }
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const int line = static_cast<int>(i);
        layout.rows.push_back({line, {}, lines[i].color, 0.0f});
        bool wrapped = false;  // on a later row of the line: cells follow each other, not the columns
        float column = kTextLeft, end = kTextLeft;  // the aligned column's start; the row's text end
        const auto newRow = [&] {
            layout.rows.push_back({line, {}, lines[i].color, 0.0f});
            wrapped = true;
            end = kTextLeft + kWrapIndent;
        };
        const auto place = [&](const std::string& text, float x) {
            layout.rows.back().cells.push_back({text, x});
            end = x + overlayTextWidth(text);
            layout.rows.back().right = end + kBandRight;
        };
        for (std::size_t c = 0; c < cells[i].size(); ++c) {
            std::string text = cells[i][c];
            const bool rowEmpty = layout.rows.back().cells.empty();
            float x = wrapped ? (rowEmpty ? end : end + kColumnGap) : column;
            if (c + 1 < cells[i].size()) column += columnWidth[c] + kColumnGap;
            if (text.empty()) continue;
            if (x + overlayTextWidth(text) > limit && !rowEmpty) {
                newRow();
                x = end;
            }
            // What still does not fit is split over as many rows as it needs.
            while (x + overlayTextWidth(text) > limit) {
                const std::size_t chars = fittingPrefix(text, limit - x);
                std::string head = text.substr(0, chars);
                while (head.size() > 1 && head.back() == ' ') head.pop_back();
                place(head, x);
                text = text.substr(chars);
                if (text.empty()) break;
                newRow();
                x = end;
            }
            if (!text.empty()) place(text, x);
        }
    }
    return layout;
}

void Overlay::draw(const std::vector<OverlayLine>& lines, int width, int height) {
    if (lines.empty() || width <= 0 || height <= 0) return;
    const OverlayLayout layout = layoutOverlay(lines, width, height);
    const float scale = layout.scale;
    std::vector<Vertex> vertices;
    std::vector<StbVertex> quads;
    for (std::size_t i = 0; i < layout.rows.size(); ++i) {
        const OverlayRow& row = layout.rows[i];
        const float y = 3.0f + kOverlayRowHeight * static_cast<float>(i);
        // The band behind the text goes first (drawn under it).
        addQuad(vertices, glm::vec2(kBandLeft, y - 2.0f) * scale,
                glm::vec2(std::max(row.right, kTextLeft + kBandRight), y + kOverlayRowHeight - 2.0f) * scale,
                {0, 0, 0, 150});
        unsigned char color[4] = {row.color.r, row.color.g, row.color.b, row.color.a};
        for (const OverlayCell& cell : row.cells) {
            std::string text = cell.text;  // stb_easy_font wants a mutable char*
            quads.resize(text.size() * 70 + 16);  // stb: well under 70 vertices per character
            const int count = stb_easy_font_print(cell.x, y, text.data(), color, quads.data(),
                                                  static_cast<int>(quads.size() * sizeof(StbVertex)));
            for (int q = 0; q < count; ++q) {
                const StbVertex* v = &quads[4 * q];
                addQuad(vertices, glm::vec2(v[0].x, v[0].y) * scale, glm::vec2(v[2].x, v[2].y) * scale,
                        {v[0].color[0], v[0].color[1], v[0].color[2], v[0].color[3]});
            }
        }
    }
    const std::size_t bytes = vertices.size() * sizeof(Vertex);
    if (vertices_.size() < bytes) {
        vertices_ = engine::gl::Buffer::create(std::max(bytes, vertices_.size() * 2), nullptr, GL_DYNAMIC_STORAGE_BIT);
        vertexArray_.attribute(0, vertices_, 2, GL_FLOAT, sizeof(Vertex), offsetof(Vertex, x));
        vertexArray_.attribute(1, vertices_, 4, GL_UNSIGNED_BYTE, sizeof(Vertex), offsetof(Vertex, color), true);
    }
    vertices_.update(0, bytes, vertices.data());

    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    program_.use();
    program_.set("uViewport", glm::vec2(static_cast<float>(width), static_cast<float>(height)));
    vertexArray_.bind();
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
    glDisable(GL_BLEND);
}

} // namespace engine_view
