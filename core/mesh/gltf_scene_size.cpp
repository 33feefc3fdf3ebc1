#include "core/mesh/gltf_scene_size.h"

#include "core/mesh/mesh_load_error.h"
#include "core/mesh/reader_support.h"

#include <tiny_gltf.h>

#include <algorithm>

namespace trimlab {

namespace {

// The accessor reader's own bound for an accessor without a buffer view (gltf_accessor.cpp).
std::uint64_t viewlessLimit(const tinygltf::Model& model)
{
    std::uint64_t bytes = 0;
    for (const tinygltf::Buffer& buffer : model.buffers)
        bytes += buffer.data.size();
    return std::max<std::uint64_t>(bytes, 1u << 20);
}

std::uint64_t declaredElements(const tinygltf::Model& model, int index, std::uint64_t viewless)
{
    if (index < 0 || std::size_t(index) >= model.accessors.size())
        return 0;
    const tinygltf::Accessor& a = model.accessors[std::size_t(index)];
    if (a.bufferView < 0)
        return a.count <= viewless ? a.count : 0;
    if (std::size_t(a.bufferView) >= model.bufferViews.size())
        return 0;
    const std::uint64_t viewBytes = model.bufferViews[std::size_t(a.bufferView)].byteLength;
    // At least one byte per element: a count beyond the view's bytes cannot fit.
    return a.byteOffset <= viewBytes && std::uint64_t(a.count) <= viewBytes - a.byteOffset ? a.count : 0;
}

} // namespace

GltfSceneSize gltfSceneSize(const tinygltf::Model& model, const std::vector<std::size_t>& nodes)
{
    const std::uint64_t viewless = viewlessLimit(model);
    GltfSceneSize size;
    for (const std::size_t node : nodes) {
        if (node >= model.nodes.size())
            continue;
        const int mesh = model.nodes[node].mesh;
        if (mesh < 0 || std::size_t(mesh) >= model.meshes.size())
            continue;
        ++size.instances;
        for (const tinygltf::Primitive& p : model.meshes[std::size_t(mesh)].primitives) {
            const auto position = p.attributes.find("POSITION");
            const std::uint64_t count =
                position == p.attributes.end() ? 0 : declaredElements(model, position->second, viewless);
            size.vertices += count;
            size.indices += p.indices >= 0 ? declaredElements(model, p.indices, viewless) : count;
            for (const auto& target : p.targets) {
                const auto displaced = target.find("POSITION");
                if (displaced != target.end())
                    size.targetVertices += declaredElements(model, displaced->second, viewless);
            }
        }
    }
    return size;
}

std::vector<int> gltfSceneRoots(const tinygltf::Model& model, const std::string& name)
{
    if (model.defaultScene >= static_cast<int>(model.scenes.size()) || model.defaultScene < -1)
        throw MeshLoadError(name, "the default scene " + std::to_string(model.defaultScene) +
                                      " does not exist (the file has " + std::to_string(model.scenes.size()) + ")");
    if (!model.scenes.empty())
        return model.scenes[static_cast<std::size_t>(std::max(model.defaultScene, 0))].nodes;
    std::vector<char> isChild(model.nodes.size(), 0);
    for (const tinygltf::Node& node : model.nodes) {
        for (const int child : node.children) {
            if (child >= 0 && static_cast<std::size_t>(child) < isChild.size())
                isChild[static_cast<std::size_t>(child)] = 1;
        }
    }
    std::vector<int> roots;
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        if (!isChild[i])
            roots.push_back(static_cast<int>(i));
    }
    return roots;
}

std::vector<std::size_t> gltfSceneNodes(const tinygltf::Model& model, const std::vector<int>& roots,
                                        const std::string& name)
{
    std::vector<std::size_t> order;
    std::vector<char> visited(model.nodes.size(), 0);
    std::vector<int> stack(roots.rbegin(), roots.rend());
    while (!stack.empty()) {
        const int node = stack.back();
        stack.pop_back();
        if (node < 0 || std::size_t(node) >= model.nodes.size())
            throw MeshLoadError(name, "node " + std::to_string(node) + " does not exist (the file has " +
                                          countNoun(model.nodes.size(), "node", "nodes") + ")");
        if (visited[std::size_t(node)]++)
            throw MeshLoadError(
                name, "node " + std::to_string(node) +
                          " is reached twice; glTF node hierarchies must be trees (no cycles or shared children)");
        order.push_back(std::size_t(node));
        const std::vector<int>& children = model.nodes[std::size_t(node)].children;
        stack.insert(stack.end(), children.rbegin(), children.rend());
    }
    return order;
}

} // namespace trimlab
