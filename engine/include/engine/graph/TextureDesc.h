#pragma once
// What a render-graph texture is, independent of GL: the graph compares descs to decide
// which transients may share one physical texture, and the allocator turns a desc into a
// real texture (GL formats are mapped by the GL allocator, not here).
#include <string>

namespace engine {

enum class TextureFormat { RGBA8, SRGB8_A8, RGBA16F, RGBA32F, R8, R32F, RG32F, Depth16, Depth24, Depth32F };

// A cube map's faces, in GL order: +X, -X, +Y, -Y, +Z, -Z.
constexpr int kCubeFaces = 6;

const char* toString(TextureFormat format);
bool isDepthFormat(TextureFormat format);

struct TextureDesc {
    int width = 0, height = 0;
    TextureFormat format = TextureFormat::RGBA8;
    int layers = 1;     // array layers (for a cube: cube count, each of kCubeFaces faces)
    bool cube = false;
    int samples = 1;    // per pixel: more than 1 is a multisampled 2D target (no layers, no cube)
    bool array = false; // a 2D array texture even with one layer (as an imported array is)
    bool operator==(const TextureDesc&) const = default;
};

// "2048x2048 Depth32F", plus " x4 layers" (an array) / " cube" / " 4 samples" when they apply: for messages and graphviz.
std::string toString(const TextureDesc& desc);

} // namespace engine
