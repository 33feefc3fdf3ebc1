#pragma once
/// \file
/// The node hierarchy of a glTF 2.0 asset as animation needs it: every node's local
/// transform (TRS or matrix) and morph weights, which channels overwrite, and the world
/// matrices composed down the hierarchy. Internal to the glTF animation loader.

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace trimlab {

/// A node's local transform and its morph weights. `matrix` is set for nodes that give a
/// matrix instead of TRS (such nodes cannot be animated).
struct NodeTransform {
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0}; // w, x, y, z
    glm::dvec3 scale{1.0};
    std::optional<glm::dmat4> matrix;
    std::vector<double> weights; ///< node.weights, else its mesh's weights, else empty

    [[nodiscard]] glm::dmat4 localMatrix() const;
};

/// The transforms of all nodes as the file states them (before any animation).
/// Throws MeshLoadError naming the node for malformed TRS arrays or a zero quaternion.
[[nodiscard]] std::vector<NodeTransform> fileNodeTransforms(const tinygltf::Model& model, const std::string& name);

/// The parent of every node (−1 for roots). Throws MeshLoadError when a child index does
/// not exist or the hierarchy is not a forest (a node with two parents, or a cycle).
[[nodiscard]] std::vector<int> nodeParents(const tinygltf::Model& model, const std::string& name);

/// World matrices of all nodes: parent world × local, roots are their local matrix.
/// `parents` comes from nodeParents (a forest).
[[nodiscard]] std::vector<glm::dmat4> worldMatrices(const std::vector<NodeTransform>& nodes,
                                                    const std::vector<int>& parents);

} // namespace trimlab
