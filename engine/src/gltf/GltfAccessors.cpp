#include "GltfAccessors.h"

#include "GltfValidation.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace engine::gltf {

namespace {

const char* typeName(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "an unknown type";
    }
}

const char* componentTypeName(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    default: return "an unknown component type";
    }
}

bool componentsFit(const tinygltf::Accessor& accessor, AccessorUse::Components wanted) {
    const int type = accessor.componentType;
    const bool unsignedSmall = type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    const bool signedSmall = type == TINYGLTF_COMPONENT_TYPE_BYTE || type == TINYGLTF_COMPONENT_TYPE_SHORT;
    const bool isFloat = type == TINYGLTF_COMPONENT_TYPE_FLOAT;
    switch (wanted) {
    case AccessorUse::Components::Float: return isFloat;
    case AccessorUse::Components::FloatOrNormalized: return isFloat || (unsignedSmall && accessor.normalized);
    case AccessorUse::Components::FloatOrSignedNormalized: return isFloat || (signedSmall && accessor.normalized);
    case AccessorUse::Components::Quantized: return isFloat || unsignedSmall || signedSmall;
    case AccessorUse::Components::UnsignedInteger:
        return (unsignedSmall || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) && !accessor.normalized;
    case AccessorUse::Components::FloatOrAnyNormalized:
        return isFloat || ((unsignedSmall || signedSmall) && accessor.normalized);
    }
    return false;
}

const char* describeWanted(AccessorUse::Components wanted) {
    switch (wanted) {
    case AccessorUse::Components::Float: return "FLOAT";
    case AccessorUse::Components::FloatOrNormalized: return "FLOAT or normalized UNSIGNED_BYTE/UNSIGNED_SHORT";
    case AccessorUse::Components::FloatOrSignedNormalized: return "FLOAT or normalized BYTE/SHORT";
    case AccessorUse::Components::Quantized: return "FLOAT or (UNSIGNED_)BYTE/(UNSIGNED_)SHORT";
    case AccessorUse::Components::UnsignedInteger: return "UNSIGNED_BYTE/SHORT/INT (not normalized)";
    case AccessorUse::Components::FloatOrAnyNormalized: return "FLOAT or normalized (UNSIGNED_)BYTE/(UNSIGNED_)SHORT";
    }
    return "";
}

const tinygltf::Accessor& accessorFitting(const LoadContext& context, const tinygltf::Model& model,
                                          int accessorIndex, const AccessorUse& use) {
    const tinygltf::Accessor& accessor = model.accessors[accessorIndex];
    const bool typeFits = accessor.type == use.type || (use.alternativeType != -1 && accessor.type == use.alternativeType);
    if (!typeFits || !componentsFit(accessor, use.components))
        context.fail(indexed("accessors", accessorIndex),
                     "used as " + use.usedAs + ", must be " + typeName(use.type) +
                         (use.alternativeType != -1 ? std::string(" or ") + typeName(use.alternativeType) : "") + " of " +
                         describeWanted(use.components) + ", but is " + typeName(accessor.type) + " of " +
                         (accessor.normalized ? "normalized " : "") + componentTypeName(accessor.componentType));
    return accessor;
}

// Calls visit(elementIndex, bytes) for each element, bytes pointing at its first component.
// An accessor without a bufferView is all zeros (glTF 2.0).
template <typename Visit>
void forEachElement(const tinygltf::Model& model, const tinygltf::Accessor& accessor, Visit visit) {
    static constexpr std::uint8_t kZeros[16 * 4] = {};
    const std::size_t elementBytes = componentsPerElement(accessor.type) * componentSize(accessor.componentType);
    if (accessor.bufferView < 0) {
        for (std::size_t i = 0; i < accessor.count; ++i) visit(i, kZeros);
        return;
    }
    const tinygltf::BufferView& view = model.bufferViews[accessor.bufferView];
    const std::uint8_t* first = model.buffers[view.buffer].data.data() + view.byteOffset + accessor.byteOffset;
    const std::size_t stride = view.byteStride != 0 ? view.byteStride : elementBytes;
    for (std::size_t i = 0; i < accessor.count; ++i) visit(i, first + i * stride);
}

// Components may sit at any alignment in the buffer: always memcpy.
template <typename T>
T load(const std::uint8_t* bytes) {
    T value;
    std::memcpy(&value, bytes, sizeof value);
    return value;
}

// glTF 2.0 3.11: normalized unsigned c / MAX, normalized signed max(c / MAX, -1).
float componentAsFloat(const std::uint8_t* bytes, int componentType, bool normalized) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
        const float value = load<std::uint8_t>(bytes);
        return normalized ? value / 255.0f : value;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        const float value = load<std::uint16_t>(bytes);
        return normalized ? value / 65535.0f : value;
    }
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const float value = load<std::int8_t>(bytes);
        return normalized ? std::max(value / 127.0f, -1.0f) : value;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        const float value = load<std::int16_t>(bytes);
        return normalized ? std::max(value / 32767.0f, -1.0f) : value;
    }
    default: return load<float>(bytes);
    }
}

std::uint32_t componentAsUnsigned(const std::uint8_t* bytes, int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return load<std::uint8_t>(bytes);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load<std::uint16_t>(bytes);
    default: return load<std::uint32_t>(bytes);
    }
}

} // namespace

std::vector<float> readFloatComponents(const LoadContext& context, const tinygltf::Model& model,
                                       int accessorIndex, const AccessorUse& use) {
    const tinygltf::Accessor& accessor = accessorFitting(context, model, accessorIndex, use);
    const std::size_t components = componentsPerElement(accessor.type);
    const std::size_t bytesPerComponent = componentSize(accessor.componentType);
    std::vector<float> values(accessor.count * components);
    forEachElement(model, accessor, [&](std::size_t element, const std::uint8_t* bytes) {
        for (std::size_t c = 0; c < components; ++c) {
            const float value = componentAsFloat(bytes + c * bytesPerComponent, accessor.componentType, accessor.normalized);
            if (!std::isfinite(value))
                context.fail(indexed("accessors", accessorIndex),
                             "used as " + use.usedAs + ", element " + std::to_string(element) + " holds " +
                                 formatNumber(value) + ", not a finite number");
            values[element * components + c] = value;
        }
    });
    return values;
}

std::vector<std::uint32_t> readUnsignedIntegers(const LoadContext& context, const tinygltf::Model& model,
                                                int accessorIndex, const AccessorUse& use) {
    const tinygltf::Accessor& accessor = accessorFitting(context, model, accessorIndex, use);
    const std::size_t components = componentsPerElement(accessor.type);
    const std::size_t bytesPerComponent = componentSize(accessor.componentType);
    std::vector<std::uint32_t> values(accessor.count * components);
    forEachElement(model, accessor, [&](std::size_t element, const std::uint8_t* bytes) {
        for (std::size_t c = 0; c < components; ++c)
            values[element * components + c] = componentAsUnsigned(bytes + c * bytesPerComponent, accessor.componentType);
    });
    return values;
}

} // namespace engine::gltf
