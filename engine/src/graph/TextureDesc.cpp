#include "engine/graph/TextureDesc.h"

namespace engine {

const char* toString(TextureFormat format) {
    switch (format) {
    case TextureFormat::RGBA8: return "RGBA8";
    case TextureFormat::SRGB8_A8: return "SRGB8_A8";
    case TextureFormat::RGBA16F: return "RGBA16F";
    case TextureFormat::RGBA32F: return "RGBA32F";
    case TextureFormat::R8: return "R8";
    case TextureFormat::R32F: return "R32F";
    case TextureFormat::RG32F: return "RG32F";
    case TextureFormat::Depth16: return "Depth16";
    case TextureFormat::Depth24: return "Depth24";
    case TextureFormat::Depth32F: return "Depth32F";
    }
    return "unknown";
}

bool isDepthFormat(TextureFormat format) {
    return format == TextureFormat::Depth16 || format == TextureFormat::Depth24 ||
           format == TextureFormat::Depth32F;
}

std::string toString(const TextureDesc& desc) {
    std::string text = std::to_string(desc.width) + "x" + std::to_string(desc.height) + " " +
                       toString(desc.format);
    if (desc.layers != 1 || desc.array) text += " x" + std::to_string(desc.layers) + " layers";
    if (desc.cube) text += " cube";
    if (desc.samples != 1) text += " " + std::to_string(desc.samples) + " samples";
    return text;
}

} // namespace engine
