// GLB layout checks (glTF 2.0 spec, "Binary glTF Layout"), all in 64-bit arithmetic.
#include "GltfContainer.h"

#include <cstring>

namespace engine::gltf {

namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kJsonChunkType = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunkType = 0x004E4942;   // "BIN\0"
constexpr std::uint64_t kHeaderBytes = 12;
constexpr std::uint64_t kChunkHeaderBytes = 8;

// GLB is little-endian, like every machine this engine runs on.
std::uint32_t readU32(std::span<const std::uint8_t> bytes, std::uint64_t offset) {
    std::uint32_t value;
    std::memcpy(&value, bytes.data() + offset, sizeof value);
    return value;
}

struct Chunk {
    std::uint32_t type = 0;
    std::span<const std::uint8_t> payload;
};

// Reads the chunk header at `offset` and checks that its payload fits in `declaredLength`.
Chunk readChunk(const LoadContext& context, std::span<const std::uint8_t> bytes,
                std::uint64_t offset, std::uint64_t declaredLength, int index, const char* expected) {
    const std::string object = "GLB chunk " + std::to_string(index) + " (" + expected + ")";
    if (offset + kChunkHeaderBytes > declaredLength)
        context.fail(object, "truncated: its 8-byte header needs bytes " + std::to_string(offset) + ".." +
                                 std::to_string(offset + kChunkHeaderBytes) + ", the file ends at " +
                                 std::to_string(declaredLength));
    const std::uint64_t length = readU32(bytes, offset);
    Chunk chunk;
    chunk.type = readU32(bytes, offset + 4);
    const std::uint64_t remaining = declaredLength - offset - kChunkHeaderBytes;
    if (length > remaining)
        context.fail(object, "length " + std::to_string(length) + " runs past the end of the file (" +
                                 std::to_string(remaining) + " bytes remain)");
    // The spec pads every chunk to 4 bytes; tinygltf 2.7.0 reports an unpadded one as an
    // error, so name it precisely here.
    if (length % 4 != 0)
        context.fail(object, "length " + std::to_string(length) + " is not a multiple of 4");
    chunk.payload = bytes.subspan(offset + kChunkHeaderBytes, length);
    return chunk;
}

} // namespace

bool hasGlbMagic(std::span<const std::uint8_t> fileBytes) {
    return fileBytes.size() >= 4 && readU32(fileBytes, 0) == kGlbMagic;
}

GltfContainer splitGlb(const LoadContext& context, std::span<const std::uint8_t> bytes) {
    const std::uint64_t fileSize = bytes.size();
    if (fileSize < kHeaderBytes)
        context.fail("GLB header", "truncated: the header needs 12 bytes, the file has " + std::to_string(fileSize));
    if (!hasGlbMagic(bytes)) context.fail("GLB header", "the magic is not 'glTF'");
    const std::uint32_t version = readU32(bytes, 4);
    if (version != 2)
        context.fail("GLB header", "version " + std::to_string(version) + " is not supported (only 2)");
    const std::uint64_t declaredLength = readU32(bytes, 8);
    if (declaredLength > fileSize)
        context.fail("GLB header", "truncated: the header says " + std::to_string(declaredLength) +
                                       " bytes, the file has " + std::to_string(fileSize));
    if (declaredLength < fileSize)
        context.fail("GLB header", "the header says " + std::to_string(declaredLength) +
                                       " bytes, but the file has " + std::to_string(fileSize));

    GltfContainer container;
    container.binary = true;
    const Chunk json = readChunk(context, bytes, kHeaderBytes, declaredLength, 0, "JSON");
    if (json.type != kJsonChunkType) context.fail("GLB chunk 0 (JSON)", "the first chunk is not of type JSON");
    if (json.payload.empty()) context.fail("GLB chunk 0 (JSON)", "the JSON chunk is empty");
    container.json = {reinterpret_cast<const char*>(json.payload.data()), json.payload.size()};

    const std::uint64_t binOffset = kHeaderBytes + kChunkHeaderBytes + json.payload.size();
    if (binOffset < declaredLength) {
        const Chunk bin = readChunk(context, bytes, binOffset, declaredLength, 1, "BIN");
        if (bin.type != kBinChunkType) context.fail("GLB chunk 1 (BIN)", "the second chunk is not of type BIN");
        // tinygltf 2.7.0 refuses an empty BIN chunk (the spec says to omit it instead).
        if (bin.payload.empty()) context.fail("GLB chunk 1 (BIN)", "the BIN chunk is empty");
        container.bin = bin.payload;
        // Chunks after BIN are allowed by the spec and ignored, by tinygltf as by us.
    }
    return container;
}

std::vector<std::uint8_t> joinGlb(std::string_view json, std::span<const std::uint8_t> bin) {
    std::vector<std::uint8_t> bytes(kHeaderBytes);
    const auto appendU32 = [&bytes](std::uint32_t value) {
        for (int shift = 0; shift < 32; shift += 8) bytes.push_back(static_cast<std::uint8_t>(value >> shift));
    };
    const auto appendChunk = [&](std::uint32_t type, const std::uint8_t* data, std::size_t size, std::uint8_t pad) {
        const std::size_t padded = (size + 3) / 4 * 4;
        appendU32(static_cast<std::uint32_t>(padded));
        appendU32(type);
        bytes.insert(bytes.end(), data, data + size);
        bytes.insert(bytes.end(), padded - size, pad);
    };
    appendChunk(kJsonChunkType, reinterpret_cast<const std::uint8_t*>(json.data()), json.size(), ' ');
    if (!bin.empty()) appendChunk(kBinChunkType, bin.data(), bin.size(), 0);
    const std::uint32_t header[3] = {kGlbMagic, 2, static_cast<std::uint32_t>(bytes.size())};
    for (int i = 0; i < 3; ++i)
        for (int b = 0; b < 4; ++b) bytes[i * 4 + b] = static_cast<std::uint8_t>(header[i] >> (8 * b));
    return bytes;
}

GltfContainer wholeFileAsJson(std::span<const std::uint8_t> bytes) {
    GltfContainer container;
    container.json = {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
    return container;
}

} // namespace engine::gltf
