#pragma once
// Puts a picture in the window: uploads it to a texture and blits it to the default
// framebuffer, 1:1 when it has the window's size (the shaded view: exactly the renderer's
// pixels), else scaled to fit and centred (nearest when enlarging, so map texels stay
// visible; linear when shrinking). Handles any window size, and reads the window back for
// screenshots. GL state it needs (no sRGB encoding, no scissor) is set here.
#include "Image.h"

#include "engine/gl/Framebuffer.h"
#include "engine/gl/Texture.h"

#include <filesystem>

namespace engine_view {

class Presenter {
public:
    // Draws `image` into the back buffer of a window whose framebuffer is `width` x `height`.
    void present(const Image& image, int width, int height);
    // The back buffer as it is now (after present and the overlay), RGB, top row first.
    Image readWindow(int width, int height) const;
    // readWindow written as an RGB PNG (through a temporary file and a rename).
    void screenshot(const std::filesystem::path& path, int width, int height) const;

private:
    engine::gl::Texture texture_;
    engine::gl::Framebuffer framebuffer_;
};

} // namespace engine_view
