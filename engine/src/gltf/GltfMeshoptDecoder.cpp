#include "GltfMeshoptDecoder.h"

#include "GltfJsonFields.h"
#include "GltfCompressionPlaceholders.h"

#include <meshoptimizer.h>

#include <optional>

namespace engine::gltf {

namespace {

constexpr const char* kExtension = "EXT_meshopt_compression";

enum class Mode { Attributes, Triangles, Indices };
enum class Filter { None, Octahedral, Quaternion, Exponential };

// The extension object of one bufferView, every member checked against the spec's ranges.
struct CompressedView {
    std::size_t buffer = 0;
    std::uint64_t byteOffset = 0;
    std::uint64_t byteLength = 0;
    std::uint64_t byteStride = 0;
    std::uint64_t count = 0;
    Mode mode = Mode::Attributes;
    Filter filter = Filter::None;
};

std::string stringMember(const JsonFields& fields, const char* key, const char* fallback) {
    const nlohmann::json* value = fields.find(key);
    if (!value) {
        if (fallback) return fallback;
        fields.fail(key, "is missing");
    }
    if (!value->is_string()) fields.fail(key, "is not a string");
    return value->get<std::string>();
}

std::uint64_t requiredIndex(const JsonFields& fields, const char* key) {
    const std::optional<std::uint64_t> value = fields.index(key);
    if (!value) fields.fail(key, "is missing");
    return *value;
}

// `fileBuffers`: how many buffers the file has (decoded views append more, which no file
// may name).
CompressedView readExtension(const LoadContext& context, const JsonFields& fields, std::size_t fileBuffers) {
    CompressedView view;
    const std::uint64_t buffer = requiredIndex(fields, "buffer");
    if (buffer >= fileBuffers)
        fields.fail("buffer", std::to_string(buffer) + " does not exist (there are " + std::to_string(fileBuffers) + ")");
    view.buffer = static_cast<std::size_t>(buffer);
    view.byteOffset = fields.index("byteOffset").value_or(0);
    view.byteLength = requiredIndex(fields, "byteLength");
    view.byteStride = requiredIndex(fields, "byteStride");
    view.count = requiredIndex(fields, "count");
    if (view.count == 0) fields.fail("count", "is 0");
    if (view.count > context.options.maxElementCount)
        fields.fail("count", std::to_string(view.count) + " is more than the limit of " +
                                 std::to_string(context.options.maxElementCount));

    const std::string mode = stringMember(fields, "mode", nullptr);
    if (mode == "ATTRIBUTES") view.mode = Mode::Attributes;
    else if (mode == "TRIANGLES") view.mode = Mode::Triangles;
    else if (mode == "INDICES") view.mode = Mode::Indices;
    else fields.fail("mode", "'" + mode + "' is not ATTRIBUTES, TRIANGLES or INDICES");

    const std::string filter = stringMember(fields, "filter", "NONE");
    if (filter == "NONE") view.filter = Filter::None;
    else if (filter == "OCTAHEDRAL") view.filter = Filter::Octahedral;
    else if (filter == "QUATERNION") view.filter = Filter::Quaternion;
    else if (filter == "EXPONENTIAL") view.filter = Filter::Exponential;
    else fields.fail("filter", "'" + filter + "' is not NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL");

    // libmeshoptimizer asserts on these, so they are refused before any call.
    if (view.mode == Mode::Attributes) {
        if (view.byteStride == 0 || view.byteStride > 256 || view.byteStride % 4 != 0)
            fields.fail("byteStride", std::to_string(view.byteStride) + " is not a multiple of 4 in [4, 256] (mode ATTRIBUTES)");
    } else {
        if (view.byteStride != 2 && view.byteStride != 4)
            fields.fail("byteStride", std::to_string(view.byteStride) + " is not 2 or 4 (mode " + mode + ")");
        if (view.filter != Filter::None) fields.fail("filter", "'" + filter + "' is only for mode ATTRIBUTES");
    }
    if (view.mode == Mode::Triangles && view.count % 3 != 0)
        fields.fail("count", std::to_string(view.count) + " is not a multiple of 3 (mode TRIANGLES)");
    if (view.filter == Filter::Octahedral && view.byteStride != 4 && view.byteStride != 8)
        fields.fail("byteStride", std::to_string(view.byteStride) + " is not 4 or 8 (filter OCTAHEDRAL)");
    if (view.filter == Filter::Quaternion && view.byteStride != 8)
        fields.fail("byteStride", std::to_string(view.byteStride) + " is not 8 (filter QUATERNION)");
    return view;
}

// The compressed bytes, or a failure when they are not all inside their buffer.
std::span<const std::uint8_t> compressedBytes(const JsonFields& fields, const CompressedView& view,
                                              const tinygltf::Model& model, const nlohmann::json& document) {
    if (isDatalessFallbackBuffer(arrayElement(document, "buffers", view.buffer)))
        fields.fail("buffer", std::to_string(view.buffer) + " is a fallback buffer without data");
    const std::vector<unsigned char>& data = model.buffers[view.buffer].data;
    std::uint64_t end = 0;
    if (__builtin_add_overflow(view.byteOffset, view.byteLength, &end) || end > data.size())
        fields.fail("byteLength", "byteOffset " + std::to_string(view.byteOffset) + " + byteLength " +
                                      std::to_string(view.byteLength) + " runs past the end of " +
                                      indexed("buffers", view.buffer) + " (" + std::to_string(data.size()) + " bytes)");
    return {data.data() + view.byteOffset, static_cast<std::size_t>(view.byteLength)};
}

// The decoded bytes, or the name of the meshoptimizer call that refused the stream.
std::vector<std::uint8_t> decode(const LoadContext& context, const std::string& object, const CompressedView& view,
                                 std::span<const std::uint8_t> source) {
    const std::size_t count = static_cast<std::size_t>(view.count);
    const std::size_t stride = static_cast<std::size_t>(view.byteStride);
    std::vector<std::uint8_t> decoded(count * stride);
    int status = 0;
    const char* call = "";
    switch (view.mode) {
    case Mode::Attributes:
        call = "meshopt_decodeVertexBuffer";
        status = meshopt_decodeVertexBuffer(decoded.data(), count, stride, source.data(), source.size());
        break;
    case Mode::Triangles:
        call = "meshopt_decodeIndexBuffer";
        status = meshopt_decodeIndexBuffer(decoded.data(), count, stride, source.data(), source.size());
        break;
    case Mode::Indices:
        call = "meshopt_decodeIndexSequence";
        status = meshopt_decodeIndexSequence(decoded.data(), count, stride, source.data(), source.size());
        break;
    }
    if (status != 0)
        context.fail(object, std::string("extensions.") + kExtension + " data does not decode (" + call + " returned " + std::to_string(status) +
                            ": corrupt or truncated stream)");
    switch (view.filter) {
    case Filter::None: break;
    case Filter::Octahedral: meshopt_decodeFilterOct(decoded.data(), count, stride); break;
    case Filter::Quaternion: meshopt_decodeFilterQuat(decoded.data(), count, stride); break;
    case Filter::Exponential: meshopt_decodeFilterExp(decoded.data(), count, stride); break;
    }
    return decoded;
}

} // namespace

void decodeMeshoptBufferViews(const LoadContext& context, const nlohmann::json& document, tinygltf::Model& model) {
    const std::size_t fileBuffers = model.buffers.size();
    for (std::size_t i = 0; i < model.bufferViews.size(); ++i) {
        tinygltf::BufferView& target = model.bufferViews[i];
        const std::string object = indexed("bufferViews", i);
        const JsonFields viewFields(context, object, arrayElement(document, "bufferViews", i), "");
        const std::optional<JsonFields> fields = viewFields.extension(kExtension);
        if (!fields) {
            const bool readsPlaceholder = target.buffer >= 0 &&
                                          isDatalessFallbackBuffer(arrayElement(document, "buffers", target.buffer));
            if (readsPlaceholder)
                context.fail(object, "reads " + indexed("buffers", target.buffer) +
                                         ", an EXT_meshopt_compression fallback buffer without data, but is not compressed");
            continue;
        }
        const CompressedView view = readExtension(context, *fields, fileBuffers);
        const std::uint64_t decodedBytes = view.count * view.byteStride;  // both capped: no overflow
        if (decodedBytes > context.options.maxFileBytes)
            fields->fail("count", "decodes to " + std::to_string(decodedBytes) + " bytes, more than the limit of " +
                                      std::to_string(context.options.maxFileBytes));
        // The view's own byteLength is what accessors are checked against: it must be the
        // decoded size, not merely fit in the (possibly dataless) fallback buffer.
        if (target.byteLength != decodedBytes)
            context.fail(object, "byteLength " + std::to_string(target.byteLength) + " is not the decoded size count " +
                                     std::to_string(view.count) + " x byteStride " + std::to_string(view.byteStride) +
                                     " = " + std::to_string(decodedBytes));
        tinygltf::Buffer decoded;
        decoded.data = decode(context, object, view, compressedBytes(*fields, view, model, document));
        model.buffers.push_back(std::move(decoded));
        target.buffer = static_cast<int>(model.buffers.size() - 1);
        target.byteOffset = 0;
    }
}

} // namespace engine::gltf
