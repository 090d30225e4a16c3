#include "GltfDracoDecoder.h"

#include "GltfJsonFields.h"
#include "GltfValidation.h"

#include <draco/compression/decode.h>

#include <cstring>
#include <limits>
#include <map>

namespace engine::gltf {

namespace {

constexpr const char* kExtension = "KHR_draco_mesh_compression";

// The extension object: the compressed view and, per attribute semantic, the Draco
// attribute's unique id.
struct DracoPrimitive {
    std::size_t bufferView = 0;
    std::map<std::string, std::uint32_t> attributes;
};

// `fileViews`: how many bufferViews the file has (decoded primitives append more, which no
// file may name).
DracoPrimitive readExtension(const JsonFields& fields, std::size_t fileViews) {
    DracoPrimitive draco;
    const std::optional<std::uint64_t> view = fields.index("bufferView");
    if (!view) fields.fail("bufferView", "is missing");
    if (*view >= fileViews)
        fields.fail("bufferView", std::to_string(*view) + " does not exist (there are " + std::to_string(fileViews) + ")");
    draco.bufferView = static_cast<std::size_t>(*view);
    const nlohmann::json* attributes = fields.find("attributes");
    if (!attributes || !attributes->is_object()) fields.fail("attributes", "is missing or not an object");
    for (const auto& [semantic, id] : attributes->items()) {
        if (!id.is_number_unsigned() || id.get<std::uint64_t>() > std::numeric_limits<std::uint32_t>::max())
            fields.fail("attributes", semantic + " is not a Draco attribute id (an unsigned 32-bit integer)");
        draco.attributes[semantic] = id.get<std::uint32_t>();
    }
    return draco;
}

// Appends `bytes` as a buffer and a view of its own; returns the view's index.
int appendView(tinygltf::Model& model, std::vector<std::uint8_t> bytes) {
    tinygltf::Buffer buffer;
    buffer.data = std::move(bytes);
    model.buffers.push_back(std::move(buffer));
    tinygltf::BufferView view;
    view.buffer = static_cast<int>(model.buffers.size() - 1);
    view.byteLength = model.buffers.back().data.size();
    model.bufferViews.push_back(std::move(view));
    return static_cast<int>(model.bufferViews.size() - 1);
}

template <typename T>
std::vector<std::uint8_t> asBytes(const std::vector<T>& values) {
    std::vector<std::uint8_t> bytes(values.size() * sizeof(T));
    std::memcpy(bytes.data(), values.data(), bytes.size());
    return bytes;
}

void pointAccessorAt(tinygltf::Accessor& accessor, int view, int componentType) {
    accessor.bufferView = view;
    accessor.byteOffset = 0;
    accessor.componentType = componentType;
    accessor.normalized = false;
}

class PrimitiveDecoder {
public:
    PrimitiveDecoder(const LoadContext& context, tinygltf::Model& model, tinygltf::Primitive& primitive, std::string object)
        : context_(context), model_(model), primitive_(primitive), object_(std::move(object)) {}

    void decode(const DracoPrimitive& draco) {
        const std::unique_ptr<draco::Mesh> mesh = decodeMesh(draco.bufferView);
        for (const auto& [semantic, id] : draco.attributes) replaceAttribute(*mesh, semantic, id);
        replaceIndices(*mesh);
        primitive_.mode = TINYGLTF_MODE_TRIANGLES;  // Draco decodes every mesh to a triangle list
    }

private:
    std::unique_ptr<draco::Mesh> decodeMesh(std::size_t viewIndex) {
        const tinygltf::BufferView& view = model_.bufferViews[viewIndex];  // validated: inside its buffer
        const unsigned char* bytes = model_.buffers[view.buffer].data.data() + view.byteOffset;
        draco::DecoderBuffer buffer;
        buffer.Init(reinterpret_cast<const char*>(bytes), view.byteLength);
        draco::Decoder decoder;
        auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
        if (!decoded.ok())
            fail("the Draco data in " + indexed("bufferViews", viewIndex) +
                 " does not decode: " + decoded.status().error_msg_string());
        std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
        if (mesh->num_points() == 0 || mesh->num_faces() == 0)
            fail("the Draco data in " + indexed("bufferViews", viewIndex) + " decodes to a mesh without triangles");
        if (mesh->num_points() > context_.options.maxElementCount ||
            std::uint64_t{mesh->num_faces()} * 3 > context_.options.maxElementCount)
            fail("the Draco mesh has more points or indices than the limit of " +
                 std::to_string(context_.options.maxElementCount));
        return mesh;
    }

    // The accessor `semantic` names is given the Draco attribute's values, one per point.
    void replaceAttribute(const draco::Mesh& mesh, const std::string& semantic, std::uint32_t id) {
        const auto found = primitive_.attributes.find(semantic);
        if (found == primitive_.attributes.end())
            fail("the Draco extension names attribute " + semantic + ", which the primitive does not have");
        tinygltf::Accessor& accessor = model_.accessors[found->second];  // references validated
        const std::string accessorName = indexed("accessors", found->second);
        const draco::PointAttribute* attribute = mesh.GetAttributeByUniqueId(id);
        if (!attribute) fail(semantic + ": the Draco mesh has no attribute with id " + std::to_string(id));
        const std::size_t components = componentsPerElement(accessor.type);
        if (components == 0 || components > 4 || attribute->num_components() != components)
            fail(semantic + ": Draco attribute " + std::to_string(id) + " has " +
                 std::to_string(attribute->num_components()) + " components, " + accessorName + " expects " +
                 std::to_string(components));
        const std::size_t points = mesh.num_points();
        if (accessor.count != points)
            fail(semantic + ": " + accessorName + " count " + std::to_string(accessor.count) +
                 " is not the Draco mesh's point count " + std::to_string(points));
        // A lying stream can leave the point-to-value map shorter than the points, or point
        // past the values: both are read unchecked by libdraco.
        if (!attribute->is_mapping_identity() && attribute->indices_map_size() < points)
            fail(semantic + ": the Draco attribute maps fewer values than there are points");
        std::vector<float> values(points * components);
        for (std::size_t p = 0; p < points; ++p) {
            const draco::AttributeValueIndex value = attribute->mapped_index(draco::PointIndex(static_cast<std::uint32_t>(p)));
            if (value.value() >= attribute->size() ||
                !attribute->ConvertValue<float>(value, static_cast<std::int8_t>(components), &values[p * components]))
                fail(semantic + ": point " + std::to_string(p) + " has no value in the Draco attribute");
        }
        pointAccessorAt(accessor, appendView(model_, asBytes(values)), TINYGLTF_COMPONENT_TYPE_FLOAT);
    }

    // The primitive's index accessor (a new one when it has none) is given the Draco faces.
    void replaceIndices(const draco::Mesh& mesh) {
        std::vector<std::uint32_t> indices;
        indices.reserve(std::size_t{mesh.num_faces()} * 3);
        for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
            for (const draco::PointIndex point : mesh.face(f)) {
                if (point.value() >= mesh.num_points())
                    fail("Draco face " + std::to_string(f.value()) + " names point " + std::to_string(point.value()) +
                         ", past the point count " + std::to_string(mesh.num_points()));
                indices.push_back(point.value());
            }
        if (primitive_.indices < 0) {
            tinygltf::Accessor accessor;
            accessor.type = TINYGLTF_TYPE_SCALAR;
            accessor.count = indices.size();
            model_.accessors.push_back(std::move(accessor));
            primitive_.indices = static_cast<int>(model_.accessors.size() - 1);
        }
        tinygltf::Accessor& accessor = model_.accessors[primitive_.indices];
        if (accessor.count != indices.size())
            fail("indices: " + indexed("accessors", primitive_.indices) + " count " + std::to_string(accessor.count) +
                 " is not the Draco mesh's index count " + std::to_string(indices.size()));
        pointAccessorAt(accessor, appendView(model_, asBytes(indices)), TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
    }

    [[noreturn]] void fail(const std::string& reason) const {
        context_.fail(object_, std::string("extensions.") + kExtension + ": " + reason);
    }

    const LoadContext& context_;
    tinygltf::Model& model_;
    tinygltf::Primitive& primitive_;
    std::string object_;
};

} // namespace

void decodeDracoPrimitives(const LoadContext& context, const nlohmann::json& document, tinygltf::Model& model) {
    const std::size_t fileViews = model.bufferViews.size();
    for (std::size_t m = 0; m < model.meshes.size(); ++m) {
        const nlohmann::json& meshJson = arrayElement(document, "meshes", m);
        for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            const std::string object = indexedNamed("meshes", m, model.meshes[m].name) + "." + indexed("primitives", p);
            const JsonFields fields(context, object, arrayElement(meshJson, "primitives", p), "");
            if (const std::optional<JsonFields> extension = fields.extension(kExtension)) {
                const DracoPrimitive draco = readExtension(*extension, fileViews);
                PrimitiveDecoder(context, model, model.meshes[m].primitives[p], object).decode(draco);
            }
        }
    }
}

} // namespace engine::gltf
