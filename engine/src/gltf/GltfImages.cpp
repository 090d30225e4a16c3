#include "GltfImages.h"

#include <stb_image.h>

#include <climits>
#include <cstring>
#include <memory>
#include <span>

namespace engine::gltf {

namespace {

bool isPng(std::span<const std::uint8_t> bytes) {
    static constexpr std::uint8_t kMagic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    return bytes.size() >= sizeof kMagic && std::memcmp(bytes.data(), kMagic, sizeof kMagic) == 0;
}

bool isJpeg(std::span<const std::uint8_t> bytes) {
    return bytes.size() >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF;
}

// stb_image 2.27 (Debian 12) writes out of bounds when a JPEG Huffman table (DHT segment)
// declares more than 256 codes (upstream nothings/stb#1289, fixed in 2.28), already in
// stbi_info_from_memory. Read every DHT as stb would (bytes past the end count as 0) and
// refuse such files first. Entropy-coded data stuffs FF with 00, so FF C4 is only a marker.
bool jpegHuffmanTablesFit(std::span<const std::uint8_t> bytes) {
    const auto at = [&](std::size_t i) -> unsigned { return i < bytes.size() ? bytes[i] : 0u; };
    for (std::size_t marker = 0; marker + 1 < bytes.size(); ++marker) {
        if (bytes[marker] != 0xFF || bytes[marker + 1] != 0xC4) continue;
        std::size_t position = marker + 4;  // after the marker and the segment length
        long remaining = static_cast<long>((at(marker + 2) << 8) | at(marker + 3)) - 2;
        while (remaining > 0) {
            unsigned codes = 0;
            for (std::size_t i = 0; i < 16; ++i) codes += at(position + 1 + i);
            if (codes > 256) return false;
            position += 17 + codes;
            remaining -= 17 + static_cast<long>(codes);
        }
    }
    return true;
}

// The encoded bytes: kept from the URI by GltfParse, or the (validated) bufferView range.
std::span<const std::uint8_t> encodedBytes(const ParsedGltf& parsed, std::size_t index) {
    const tinygltf::Image& image = parsed.model.images[index];
    if (image.bufferView < 0) return parsed.uriImageBytes[index];
    const tinygltf::BufferView& view = parsed.model.bufferViews[image.bufferView];
    return std::span<const std::uint8_t>(parsed.model.buffers[view.buffer].data)
        .subspan(view.byteOffset, view.byteLength);
}

Image decodeImage(const LoadContext& context, const ParsedGltf& parsed, std::size_t index) {
    const tinygltf::Image& source = parsed.model.images[index];
    const std::string object = indexedNamed("images", index, source.name);
    const std::span<const std::uint8_t> bytes = encodedBytes(parsed, index);
    if (bytes.empty()) context.fail(object, "has no data");
    if (!isPng(bytes) && !isJpeg(bytes))
        context.fail(object, "is not a PNG or JPEG file" +
                                 (source.mimeType.empty() ? std::string() : " (mimeType " + source.mimeType + ")"));
    if (bytes.size() > static_cast<std::size_t>(INT_MAX)) context.fail(object, "is 2 GiB or larger");
    if (isJpeg(bytes) && !jpegHuffmanTablesFit(bytes))
        context.fail(object, "is a corrupt JPEG: a Huffman table declares more than 256 codes");
    const int length = static_cast<int>(bytes.size());

    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(bytes.data(), length, &width, &height, &channels))
        context.fail(object, std::string("cannot read the image header: ") + stbi_failure_reason());
    const int limit = context.options.maxImageDimension;
    if (width <= 0 || height <= 0 || width > limit || height > limit)
        context.fail(object, std::to_string(width) + "x" + std::to_string(height) +
                                 " pixels is outside 1.." + std::to_string(limit) + " per side");

    const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(bytes.data(), length, &width, &height, &channels, 4), &stbi_image_free);
    if (!pixels) context.fail(object, std::string("failed to decode: ") + stbi_failure_reason());

    Image image;
    image.name = !source.name.empty() ? source.name : source.uri;
    image.width = width;
    image.height = height;
    image.rgba8.assign(pixels.get(), pixels.get() + static_cast<std::size_t>(width) * height * 4);
    return image;
}

} // namespace

std::vector<Image> decodeImages(const LoadContext& context, const ParsedGltf& parsed) {
    std::vector<Image> images;
    images.reserve(parsed.model.images.size());
    for (std::size_t i = 0; i < parsed.model.images.size(); ++i) images.push_back(decodeImage(context, parsed, i));
    return images;
}

} // namespace engine::gltf
