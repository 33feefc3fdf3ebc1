#include "core/io/gltf_builder.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

namespace trimlab::io {

int addGltfBufferView(tinygltf::Model& model, const void* bytes, std::size_t size, int target)
{
    std::vector<unsigned char>& data = model.buffers[0].data;
    data.resize((data.size() + 3) / 4 * 4, 0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = size;
    view.target = target;
    const auto* begin = static_cast<const unsigned char*>(bytes);
    data.insert(data.end(), begin, begin + size);
    model.bufferViews.push_back(view);
    return int(model.bufferViews.size() - 1);
}

int addGltfAccessor(tinygltf::Model& model, int view, int componentType, int type, std::size_t count)
{
    tinygltf::Accessor accessor;
    accessor.bufferView = view;
    accessor.componentType = componentType;
    accessor.type = type;
    accessor.count = count;
    model.accessors.push_back(accessor);
    return int(model.accessors.size() - 1);
}

namespace {

void setVec3Bounds(tinygltf::Accessor& accessor, std::span<const glm::vec3> values)
{
    glm::vec3 low = values.empty() ? glm::vec3(0.0f) : values.front();
    glm::vec3 high = low;
    for (const glm::vec3& v : values) {
        low = glm::min(low, v);
        high = glm::max(high, v);
    }
    accessor.minValues = {low.x, low.y, low.z};
    accessor.maxValues = {high.x, high.y, high.z};
}

} // namespace

namespace {

// glTF (§3.6.2.2) and every reader require finite floats; a non-finite value means a
// computation went wrong upstream, and writing it would hand the problem to the next tool.
void requireFinite(const float* values, std::size_t count, std::size_t components, std::size_t accessor)
{
    for (std::size_t i = 0; i < count; ++i)
        if (!std::isfinite(values[i]))
            throw std::invalid_argument("accessor " + std::to_string(accessor) + ", element " +
                                        std::to_string(i / components) + ": a non-finite value (" +
                                        std::to_string(values[i]) + ") cannot be written to glTF");
}

} // namespace

int addGltfVec3Accessor(tinygltf::Model& model, const std::vector<glm::vec3>& values, int target, bool bounds)
{
    requireFinite(reinterpret_cast<const float*>(values.data()), values.size() * 3, 3, model.accessors.size());
    const int view = addGltfBufferView(model, values.data(), values.size() * sizeof(glm::vec3), target);
    const int accessor = addGltfAccessor(model, view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, values.size());
    if (bounds && !values.empty())
        setVec3Bounds(model.accessors[std::size_t(accessor)], values);
    return accessor;
}

int addGltfFloatAccessor(tinygltf::Model& model, const std::vector<float>& values, int type, bool bounds)
{
    const std::size_t components = std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(type)));
    requireFinite(values.data(), values.size(), std::max<std::size_t>(components, 1), model.accessors.size());
    const int view = addGltfBufferView(model, values.data(), values.size() * sizeof(float), 0);
    const int accessor = addGltfAccessor(model, view, TINYGLTF_COMPONENT_TYPE_FLOAT, type, values.size() / components);
    if (bounds && type == TINYGLTF_TYPE_SCALAR && !values.empty()) {
        const auto [low, high] = std::minmax_element(values.begin(), values.end());
        model.accessors[std::size_t(accessor)].minValues = {*low};
        model.accessors[std::size_t(accessor)].maxValues = {*high};
    }
    return accessor;
}

int addGltfSparseVec3Accessor(tinygltf::Model& model, const std::vector<glm::vec3>& values)
{
    requireFinite(reinterpret_cast<const float*>(values.data()), values.size() * 3, 3, model.accessors.size());
    std::vector<std::uint32_t> indices;
    std::vector<glm::vec3> nonZero;
    for (std::size_t v = 0; v < values.size(); ++v) {
        if (values[v] != glm::vec3(0.0f)) {
            indices.push_back(std::uint32_t(v));
            nonZero.push_back(values[v]);
        }
    }
    // Without a buffer view the accessor is all zeros; sparse parts need >= 1 element.
    const int accessor = addGltfAccessor(model, -1, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, values.size());
    if (!indices.empty()) {
        const int indexView = addGltfBufferView(model, indices.data(), indices.size() * sizeof(std::uint32_t), 0);
        const int valueView = addGltfBufferView(model, nonZero.data(), nonZero.size() * sizeof(glm::vec3), 0);
        tinygltf::Accessor& a = model.accessors[std::size_t(accessor)];
        a.sparse.isSparse = true;
        a.sparse.count = int(indices.size());
        a.sparse.indices.bufferView = indexView;
        a.sparse.indices.byteOffset = 0;
        a.sparse.indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        a.sparse.values.bufferView = valueView;
        a.sparse.values.byteOffset = 0;
    }
    // min/max cover the whole accessor, zeros included unless every value is non-zero.
    if (indices.size() < values.size())
        nonZero.emplace_back(0.0f);
    setVec3Bounds(model.accessors[std::size_t(accessor)], nonZero);
    return accessor;
}

int addGltfTriangleIndices(tinygltf::Model& model, const std::vector<glm::uvec3>& triangles)
{
    const int view = addGltfBufferView(model, triangles.data(), triangles.size() * sizeof(glm::uvec3),
                                       TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    return addGltfAccessor(model, view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                           3 * triangles.size());
}

int addGltfSingleMeshScene(tinygltf::Model& model, const tinygltf::Primitive& primitive, const std::string& name,
                           int skin)
{
    tinygltf::Mesh mesh;
    mesh.name = name;
    mesh.primitives.push_back(primitive);
    model.meshes.push_back(mesh);
    tinygltf::Node node;
    node.name = name;
    node.mesh = int(model.meshes.size() - 1);
    node.skin = skin;
    model.nodes.push_back(node);
    const int nodeIndex = int(model.nodes.size() - 1);
    tinygltf::Scene scene;
    scene.nodes = {nodeIndex};
    model.scenes.push_back(scene);
    model.defaultScene = int(model.scenes.size() - 1);
    return nodeIndex;
}

void addGltfMorphStepAnimation(tinygltf::Model& model, const std::string& name, const std::vector<float>& times,
                               std::size_t firstTargetKey)
{
    const std::size_t keys = times.size();
    const std::size_t targets = keys - firstTargetKey;
    std::vector<float> weights(keys * targets, 0.0f); // row-major [keyframe][target]
    for (std::size_t k = firstTargetKey; k < keys; ++k)
        weights[k * targets + (k - firstTargetKey)] = 1.0f;
    tinygltf::AnimationSampler sampler;
    sampler.input = addGltfFloatAccessor(model, times, TINYGLTF_TYPE_SCALAR, true);
    sampler.output = addGltfFloatAccessor(model, weights, TINYGLTF_TYPE_SCALAR, false);
    sampler.interpolation = "STEP";
    tinygltf::AnimationChannel channel;
    channel.sampler = 0;
    channel.target_node = 0;
    channel.target_path = "weights";
    tinygltf::Animation animation;
    animation.name = name;
    animation.samplers.push_back(sampler);
    animation.channels.push_back(channel);
    model.animations.push_back(animation);
}

} // namespace trimlab::io
