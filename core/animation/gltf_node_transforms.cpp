#include "core/animation/gltf_node_transforms.h"

#include "core/mesh/mesh_load_error.h"

#include <tiny_gltf.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace trimlab {

namespace {

void requireCount(const std::vector<double>& values, std::size_t count, const char* what, std::size_t node,
                  const std::string& name)
{
    if (!values.empty() && values.size() != count)
        throw MeshLoadError(name,
                            std::string("'") + what + "' must have " + std::to_string(count) + " numbers, not " +
                                std::to_string(values.size()),
                            {.line = 0, .element = "node " + std::to_string(node)});
}

NodeTransform fileTransform(const tinygltf::Model& model, std::size_t index, const std::string& name)
{
    const tinygltf::Node& node = model.nodes[index];
    requireCount(node.matrix, 16, "matrix", index, name);
    requireCount(node.translation, 3, "translation", index, name);
    requireCount(node.rotation, 4, "rotation", index, name);
    requireCount(node.scale, 3, "scale", index, name);
    NodeTransform transform;
    if (!node.matrix.empty())
        transform.matrix = glm::make_mat4(node.matrix.data()); // column-major, as glTF stores it
    if (!node.translation.empty())
        transform.translation = glm::make_vec3(node.translation.data());
    if (!node.rotation.empty()) {
        const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        if (!(glm::length(q) > 0.0))
            throw MeshLoadError(name, "the rotation quaternion is zero",
                                {.line = 0, .element = "node " + std::to_string(index)});
        transform.rotation = glm::normalize(q);
    }
    if (!node.scale.empty())
        transform.scale = glm::make_vec3(node.scale.data());
    transform.weights = node.weights;
    if (transform.weights.empty() && node.mesh >= 0 && std::size_t(node.mesh) < model.meshes.size())
        transform.weights = model.meshes[std::size_t(node.mesh)].weights;
    return transform;
}

} // namespace

glm::dmat4 NodeTransform::localMatrix() const
{
    if (matrix)
        return *matrix;
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), translation);
    m *= glm::mat4_cast(rotation);
    return glm::scale(m, scale);
}

std::vector<NodeTransform> fileNodeTransforms(const tinygltf::Model& model, const std::string& name)
{
    std::vector<NodeTransform> nodes;
    nodes.reserve(model.nodes.size());
    for (std::size_t i = 0; i < model.nodes.size(); ++i)
        nodes.push_back(fileTransform(model, i, name));
    return nodes;
}

std::vector<int> nodeParents(const tinygltf::Model& model, const std::string& name)
{
    std::vector<int> parents(model.nodes.size(), -1);
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        for (const int child : model.nodes[i].children) {
            if (child < 0 || std::size_t(child) >= model.nodes.size())
                throw MeshLoadError(name, "child node " + std::to_string(child) + " does not exist",
                                    {.line = 0, .element = "node " + std::to_string(i)});
            if (parents[std::size_t(child)] >= 0 || std::size_t(child) == i)
                throw MeshLoadError(name, "node " + std::to_string(child) +
                                              " has two parents; glTF node hierarchies must be trees");
            parents[std::size_t(child)] = int(i);
        }
    }
    // Walking up from every node must reach a root, else a cycle. Each walk stops at the
    // first node an earlier walk settled, so every node is visited once: linear time even
    // for a chain of a million nodes.
    enum : char { kUnseen, kOnWalk, kSettled };
    std::vector<char> state(parents.size(), kUnseen);
    std::vector<std::size_t> walk;
    for (std::size_t i = 0; i < parents.size(); ++i) {
        walk.clear();
        for (int node = int(i); node >= 0 && state[std::size_t(node)] != kSettled; node = parents[std::size_t(node)]) {
            if (state[std::size_t(node)] == kOnWalk)
                throw MeshLoadError(name, "node " + std::to_string(node) +
                                              " is part of a cycle; glTF node hierarchies must be trees");
            state[std::size_t(node)] = kOnWalk;
            walk.push_back(std::size_t(node));
        }
        for (const std::size_t node : walk)
            state[node] = kSettled;
    }
    return parents;
}

std::vector<glm::dmat4> worldMatrices(const std::vector<NodeTransform>& nodes, const std::vector<int>& parents)
{
    std::vector<glm::dmat4> world(nodes.size());
    std::vector<char> done(nodes.size(), 0);
    std::vector<std::size_t> chain;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        // Collect the not yet computed ancestors, then compose from the top down.
        chain.clear();
        for (int n = int(i); n >= 0 && !done[std::size_t(n)]; n = parents[std::size_t(n)])
            chain.push_back(std::size_t(n));
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            const int parent = parents[*it];
            const glm::dmat4 local = nodes[*it].localMatrix();
            world[*it] = parent >= 0 ? world[std::size_t(parent)] * local : local;
            done[*it] = 1;
        }
    }
    return world;
}

} // namespace trimlab
