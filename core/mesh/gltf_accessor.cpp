#include "core/mesh/gltf_accessor.h"

#include "core/mesh/byte_cursor.h"
#include "core/mesh/mesh_load_error.h"
#include "core/mesh/reader_support.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <string_view>

namespace trimlab {

namespace {

[[noreturn]] void fail(const GltfReadContext& context, int accessor, const std::string& reason)
{
    throw MeshLoadError(context.displayName, "accessor " + std::to_string(accessor) + ": " + reason,
                        {.line = 0, .element = context.element});
}

// The bytes of one run of elements (an accessor, or the indices/values of its sparse
// part), with every element known to lie inside its buffer view and buffer.
struct ElementRun {
    std::string_view bytes; // starts at the first element
    std::size_t stride = 0;
};

std::string rangeText(std::size_t begin, std::size_t end)
{
    return "bytes " + std::to_string(begin) + ".." + std::to_string(end);
}

ElementRun locateRun(const tinygltf::Model& model, int viewIndex, std::size_t offset, std::size_t count,
                     std::size_t elementSize, int accessor, const GltfReadContext& context)
{
    if (viewIndex < 0 || static_cast<std::size_t>(viewIndex) >= model.bufferViews.size())
        fail(context, accessor,
             "buffer view " + std::to_string(viewIndex) + " does not exist (the file has " +
                 std::to_string(model.bufferViews.size()) + ")");
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(viewIndex)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
        fail(context, accessor,
             "buffer view " + std::to_string(viewIndex) + " names buffer " + std::to_string(view.buffer) +
                 ", which does not exist");
    const std::vector<unsigned char>& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        fail(context, accessor,
             "buffer view " + std::to_string(viewIndex) + " spans " +
                 rangeText(view.byteOffset, view.byteOffset + view.byteLength) + " of buffer " +
                 std::to_string(view.buffer) + ", which has only " + std::to_string(data.size()));
    const std::size_t stride = view.byteStride == 0 ? elementSize : view.byteStride;
    if (stride < elementSize)
        fail(context, accessor,
             "the byte stride " + std::to_string(stride) + " of buffer view " + std::to_string(viewIndex) +
                 " is smaller than an element (" + std::to_string(elementSize) + " bytes)");
    const std::size_t available = view.byteLength;
    if (count == 0)
        return {std::string_view(), stride};
    const bool fits = (offset <= available && elementSize <= available - offset &&
                       (count - 1) <= (available - offset - elementSize) / stride);
    if (!fits)
        fail(context, accessor,
             std::to_string(count) + " elements of " + std::to_string(elementSize) + " bytes from byte offset " +
                 std::to_string(offset) + " do not fit in buffer view " + std::to_string(viewIndex) + " (" +
                 std::to_string(available) + " bytes)");
    const auto* base = reinterpret_cast<const char*>(data.data()) + view.byteOffset + offset;
    return {std::string_view(base, available - offset), stride};
}

double readComponent(const char* p, int componentType, bool normalized)
{
    const std::endian le = std::endian::little;
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const double v = decodeScalar<std::int8_t>(p, le);
        return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
        const double v = decodeScalar<std::uint8_t>(p, le);
        return normalized ? v / 255.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        const double v = decodeScalar<std::int16_t>(p, le);
        return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        const double v = decodeScalar<std::uint16_t>(p, le);
        return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return decodeScalar<std::uint32_t>(p, le);
    case TINYGLTF_COMPONENT_TYPE_INT:
        return decodeScalar<std::int32_t>(p, le);
    case TINYGLTF_COMPONENT_TYPE_DOUBLE:
        return decodeScalar<double>(p, le);
    default:
        return decodeScalar<float>(p, le);
    }
}

std::size_t totalBufferBytes(const tinygltf::Model& model)
{
    std::size_t total = 0;
    for (const tinygltf::Buffer& buffer : model.buffers)
        total += buffer.data.size();
    return total;
}

std::string typeName(int type)
{
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
        return "VEC2";
    case TINYGLTF_TYPE_VEC3:
        return "VEC3";
    case TINYGLTF_TYPE_VEC4:
        return "VEC4";
    case TINYGLTF_TYPE_MAT2:
        return "MAT2";
    case TINYGLTF_TYPE_MAT3:
        return "MAT3";
    case TINYGLTF_TYPE_MAT4:
        return "MAT4";
    default:
        return "type " + std::to_string(type);
    }
}

const tinygltf::Accessor& checkedAccessor(const tinygltf::Model& model, int accessor, int expectedType,
                                          const GltfReadContext& context)
{
    if (accessor < 0 || static_cast<std::size_t>(accessor) >= model.accessors.size())
        fail(context, accessor,
             "does not exist (the file has " + std::to_string(model.accessors.size()) + " accessors)");
    const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(accessor)];
    if (a.type != expectedType)
        fail(context, accessor, "has the wrong type; expected " + typeName(expectedType));
    if (tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType)) <= 0)
        fail(context, accessor, "has an unknown component type " + std::to_string(a.componentType));
    if (a.bufferView < 0 && a.count > std::max<std::size_t>(totalBufferBytes(model), 1u << 20))
        fail(context, accessor,
             "declares " + std::to_string(a.count) +
                 " elements but no data (no buffer view); refusing to allocate them");
    return a;
}

// Overwrites the elements listed in the sparse part of `a` in `values` (count × components).
void applySparse(const tinygltf::Model& model, const tinygltf::Accessor& a, int accessor, int components,
                 std::vector<double>& values, const GltfReadContext& context)
{
    const auto& sparse = a.sparse;
    const int indexType = sparse.indices.componentType;
    const int indexSize = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(indexType));
    if (sparse.count < 0 || static_cast<std::size_t>(sparse.count) > a.count || indexSize <= 0 ||
        indexType == TINYGLTF_COMPONENT_TYPE_FLOAT || sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
        fail(context, accessor, "has an invalid sparse part");
    const auto count = static_cast<std::size_t>(sparse.count);
    const std::size_t componentSize = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
    const ElementRun indices = locateRun(model, sparse.indices.bufferView, std::size_t(sparse.indices.byteOffset),
                                         count, std::size_t(indexSize), accessor, context);
    const ElementRun sparseValues = locateRun(model, sparse.values.bufferView, std::size_t(sparse.values.byteOffset),
                                              count, componentSize * std::size_t(components), accessor, context);
    for (std::size_t i = 0; i < count; ++i) {
        const double target = readComponent(indices.bytes.data() + i * std::size_t(indexSize), indexType, false);
        if (target < 0.0 || target >= static_cast<double>(a.count))
            fail(context, accessor,
                 "sparse index " + std::to_string(static_cast<long long>(target)) +
                     " is out of range (the accessor has " + std::to_string(a.count) + " elements)");
        for (int c = 0; c < components; ++c)
            values[static_cast<std::size_t>(target) * std::size_t(components) + std::size_t(c)] =
                readComponent(sparseValues.bytes.data() + i * componentSize * std::size_t(components) +
                                  std::size_t(c) * componentSize,
                              a.componentType, a.normalized);
    }
}

// All components of all elements of a validated accessor, as doubles (count × components).
std::vector<double> readComponents(const tinygltf::Model& model, const tinygltf::Accessor& a, int accessor,
                                   int components, const GltfReadContext& context)
{
    const std::size_t componentSize = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
    std::vector<double> values;
    if (a.bufferView < 0) {
        values.assign(a.count * std::size_t(components), 0.0);
    } else {
        const ElementRun run = locateRun(model, a.bufferView, a.byteOffset, a.count,
                                         componentSize * std::size_t(components), accessor, context);
        values.reserve(a.count * std::size_t(components));
        for (std::size_t i = 0; i < a.count; ++i) {
            for (int c = 0; c < components; ++c)
                values.push_back(readComponent(run.bytes.data() + i * run.stride + std::size_t(c) * componentSize,
                                               a.componentType, a.normalized));
        }
    }
    if (a.sparse.isSparse)
        applySparse(model, a, accessor, components, values, context);
    return values;
}

} // namespace

std::vector<glm::vec3> readGltfPositions(const tinygltf::Model& model, int accessor, const GltfReadContext& context)
{
    const tinygltf::Accessor& a = checkedAccessor(model, accessor, TINYGLTF_TYPE_VEC3, context);
    const std::vector<double> values = readComponents(model, a, accessor, 3, context);
    std::vector<glm::vec3> positions;
    positions.reserve(a.count);
    for (std::size_t i = 0; i < a.count; ++i) {
        for (int c = 0; c < 3; ++c) {
            const double v = values[3 * i + std::size_t(c)];
            if (!isFiniteFloat(v))
                fail(context, accessor, "position " + std::to_string(i) + ' ' + nonFiniteCoordinateReason(v));
        }
        positions.emplace_back(values[3 * i], values[3 * i + 1], values[3 * i + 2]);
    }
    return positions;
}

std::vector<double> readGltfNumbers(const tinygltf::Model& model, int accessor, int type,
                                    const GltfReadContext& context)
{
    const tinygltf::Accessor& a = checkedAccessor(model, accessor, type, context);
    const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(type));
    const bool matrix = type == TINYGLTF_TYPE_MAT2 || type == TINYGLTF_TYPE_MAT3 || type == TINYGLTF_TYPE_MAT4;
    if (components <= 0 || (matrix && a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT))
        fail(context, accessor, "matrices must be stored as FLOAT components");
    std::vector<double> values = readComponents(model, a, accessor, components, context);
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i]))
            fail(context, accessor,
                 "element " + std::to_string(i / std::size_t(components)) + " is not finite (" +
                     describeNonFinite(values[i]) + ")");
    }
    return values;
}

std::vector<std::uint32_t> readGltfIndices(const tinygltf::Model& model, int accessor, std::size_t vertexCount,
                                           const GltfReadContext& context)
{
    const tinygltf::Accessor& a = checkedAccessor(model, accessor, TINYGLTF_TYPE_SCALAR, context);
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail(context, accessor,
             "indices must be unsigned bytes, shorts or ints (component type " + std::to_string(a.componentType) + ")");
    if (a.normalized)
        fail(context, accessor, "indices must not be normalized");
    const std::vector<double> values = readComponents(model, a, accessor, 1, context);
    std::vector<std::uint32_t> indices;
    indices.reserve(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (values[i] >= static_cast<double>(vertexCount))
            fail(context, accessor,
                 "index " + std::to_string(static_cast<std::uint64_t>(values[i])) + " (element " + std::to_string(i) +
                     ") is out of range; the primitive has only " + countNoun(vertexCount, "vertex", "vertices"));
        indices.push_back(static_cast<std::uint32_t>(values[i]));
    }
    return indices;
}

} // namespace trimlab
