#include "compressed_seeds.h"

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <meshoptimizer.h>

#include <array>
#include <stdexcept>

namespace compressed_seeds {

using namespace gltf_writer;

namespace {

// Axis-aligned unit cube, four corners per face, counter-clockwise from outside.
struct Face {
    std::array<float, 3> normal;
    std::array<std::array<float, 3>, 4> corners;
};
constexpr std::array<Face, 6> kCubeFaces{{
    {{1, 0, 0}, {{{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}}},
    {{-1, 0, 0}, {{{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}}}},
    {{0, 1, 0}, {{{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}}}},
    {{0, -1, 0}, {{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}}},
    {{0, 0, 1}, {{{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}}},
    {{0, 0, -1}, {{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}}},
}};

// The view of a meshopt-compressed stream: its bytes in buffer 0 (the BIN chunk), the
// decoded data in buffer 1 (the fallback without data) at `decodedOffset`.
int addMeshoptView(GltfBuilder& b, const std::vector<unsigned char>& encoded, std::size_t& decodedOffset,
                   std::size_t count, std::size_t stride, const char* mode, const char* filter) {
    const int view = b.addView(encoded.data(), encoded.size());
    json& entry = b.doc["bufferViews"][view];
    json extension = {{"buffer", 0},          {"byteOffset", entry["byteOffset"]}, {"byteLength", encoded.size()},
                      {"byteStride", stride}, {"count", count},                    {"mode", mode}};
    if (filter) extension["filter"] = filter;
    entry = {{"buffer", 1}, {"byteOffset", decodedOffset}, {"byteLength", count * stride},
             {"extensions", {{"EXT_meshopt_compression", extension}}}};
    if (std::string(mode) == "ATTRIBUTES") entry["byteStride"] = stride;
    decodedOffset += (count * stride + 3) / 4 * 4;
    return view;
}

// `count` vertices of `stride` bytes (a multiple of 4, as the codec requires).
std::vector<unsigned char> encodeVertices(const void* vertices, std::size_t count, std::size_t stride) {
    std::vector<unsigned char> out(meshopt_encodeVertexBufferBound(count, stride));
    out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), vertices, count, stride));
    return out;
}

} // namespace

GltfBuilder dracoCube() {
    draco::TriangleSoupMeshBuilder builder;
    builder.Start(12);
    const int position = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
    const int normal = builder.AddAttribute(draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32);
    int face = 0;
    for (const Face& f : kCubeFaces)
        for (const auto& corners : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
            builder.SetAttributeValuesForFace(position, draco::FaceIndex(face), f.corners[corners[0]].data(),
                                              f.corners[corners[1]].data(), f.corners[corners[2]].data());
            builder.SetAttributeValuesForFace(normal, draco::FaceIndex(face), f.normal.data(), f.normal.data(),
                                              f.normal.data());
            ++face;
        }
    const std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
    draco::Encoder encoder;
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 11);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, 8);
    draco::EncoderBuffer encoded;
    if (!encoder.EncodeMeshToBuffer(*mesh, &encoded).ok()) throw std::runtime_error("Draco encoding failed");

    // The accessors must state the decoded counts, which deduplication decides: decode once.
    draco::DecoderBuffer input;
    input.Init(encoded.data(), encoded.size());
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&input);
    if (!decoded.ok()) throw std::runtime_error("Draco decoding failed");
    const std::unique_ptr<draco::Mesh> roundTrip = std::move(decoded).value();

    GltfBuilder b;
    b.doc["asset"]["generator"] = "tools/fuzz/make_seeds";
    const int view = b.addView(encoded.data(), encoded.size());
    const int positions = b.add("accessors", {{"componentType", kFloat}, {"count", roundTrip->num_points()}, {"type", "VEC3"}});
    // POSITION bounds are required. Draco's quantization keeps the range's ends exact, so the
    // corners' bounds are the decoded ones.
    std::vector<float> corners;
    for (const Face& f : kCubeFaces)
        for (const std::array<float, 3>& corner : f.corners) corners.insert(corners.end(), corner.begin(), corner.end());
    b.setBounds(positions, corners);
    const int normals = b.add("accessors", {{"componentType", kFloat}, {"count", roundTrip->num_points()}, {"type", "VEC3"}});
    const int indices = b.add("accessors", {{"componentType", kUnsignedShort}, {"count", roundTrip->num_faces() * 3}, {"type", "SCALAR"}});
    const json draco = {{"bufferView", view},
                        {"attributes", {{"POSITION", mesh->attribute(position)->unique_id()},
                                        {"NORMAL", mesh->attribute(normal)->unique_id()}}}};
    b.addMesh({{"attributes", {{"POSITION", positions}, {"NORMAL", normals}}},
               {"indices", indices},
               {"extensions", {{"KHR_draco_mesh_compression", draco}}}});
    b.addNode({{"mesh", 0}});
    b.setScene({0});
    b.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    b.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    return b;
}

GltfBuilder meshoptQuad() {
    struct Position { std::uint16_t x, y, z, pad; };
    const std::vector<Position> positions = {{0, 0, 0, 0}, {1023, 0, 0, 0}, {1023, 1023, 0, 0}, {0, 1023, 0, 0}};
    // Octahedral normals (x, y, z, w: the filter keeps w), not +z alone: +z's encoding reads
    // as +z even undecoded.
    const std::vector<float> unitNormals = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.6f, 0, -0.8f, 0};
    std::vector<std::int8_t> normals(16);
    meshopt_encodeFilterOct(normals.data(), 4, 4, 8, unitNormals.data());
    const std::vector<float> uv = {0, 0, 1, 0, 1, 1, 0, 1};
    std::vector<std::uint32_t> uvExp(8);
    meshopt_encodeFilterExp(uvExp.data(), 4, 8, 15, uv.data());
    const std::vector<std::uint16_t> triangles = {0, 1, 2, 0, 2, 3};
    std::vector<unsigned char> indexStream(meshopt_encodeIndexBufferBound(triangles.size(), 4));
    indexStream.resize(meshopt_encodeIndexBuffer(indexStream.data(), indexStream.size(), triangles.data(), triangles.size()));
    std::vector<unsigned char> sequenceStream(meshopt_encodeIndexSequenceBound(triangles.size(), 4));
    sequenceStream.resize(
        meshopt_encodeIndexSequence(sequenceStream.data(), sequenceStream.size(), triangles.data(), triangles.size()));

    GltfBuilder b;
    b.doc["asset"]["generator"] = "tools/fuzz/make_seeds";
    std::size_t decoded = 0;
    const int positionView = addMeshoptView(b, encodeVertices(positions.data(), 4, 8), decoded, 4, 8, "ATTRIBUTES", nullptr);
    const int normalView = addMeshoptView(b, encodeVertices(normals.data(), 4, 4), decoded, 4, 4, "ATTRIBUTES", "OCTAHEDRAL");
    const int uvView = addMeshoptView(b, encodeVertices(uvExp.data(), 4, 8), decoded, 4, 8, "ATTRIBUTES", "EXPONENTIAL");
    const int indexView = addMeshoptView(b, indexStream, decoded, 6, 2, "TRIANGLES", nullptr);
    const int sequenceView = addMeshoptView(b, sequenceStream, decoded, 6, 2, "INDICES", nullptr);
    const int positionAccessor = b.addAccessor(positionView, kUnsignedShort, 4, "VEC3");
    std::vector<float> xyz;
    for (const Position& p : positions) xyz.insert(xyz.end(), {float(p.x), float(p.y), float(p.z)});
    b.setBounds(positionAccessor, xyz);
    const int normalAccessor = b.addAccessor(normalView, 5120 /* BYTE */, 4, "VEC3", /*normalized=*/true);
    const int uvAccessor = b.addAccessor(uvView, kFloat, 4, "VEC2");
    const json attributes = {{"POSITION", positionAccessor}, {"NORMAL", normalAccessor}, {"TEXCOORD_0", uvAccessor}};
    b.doc["meshes"] = json::array({{{"primitives", json::array({
        {{"attributes", attributes}, {"indices", b.addAccessor(indexView, kUnsignedShort, 6, "SCALAR")}},
        {{"attributes", attributes}, {"indices", b.addAccessor(sequenceView, kUnsignedShort, 6, "SCALAR")}},
    })}}});
    b.addNode({{"mesh", 0}, {"scale", {1.0 / 1023, 1.0 / 1023, 1.0 / 1023}}});
    b.setScene({0});
    // Buffer 0 is the BIN chunk (glbBytes() leaves a document's own "buffers" alone).
    b.doc["buffers"] = json::array({{{"byteLength", b.bin.size()}},
                                    {{"byteLength", decoded}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}});
    const json extensions = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
    b.doc["extensionsUsed"] = extensions;
    b.doc["extensionsRequired"] = extensions;
    return b;
}

} // namespace compressed_seeds
