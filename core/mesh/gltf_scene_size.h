#pragma once
/// \file
/// The nodes of a glTF scene, walked once for both glTF readers (gltf_reader.h, the
/// animation loader's gltf_animated_geometry.h), and what they will take once read: every
/// node that shows a mesh adds all of that mesh's vertices and indices again, so a small
/// file whose many nodes reference one large mesh can ask for far more memory than it
/// holds. Counted from the accessors' declared sizes before anything is read, so that the
/// readers refuse such a file against the memory budget (core/util/memory_budget.h)
/// instead of failing halfway. Internal to the glTF readers; includes no tinygltf header.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace trimlab {

struct GltfSceneSize {
    std::uint64_t instances = 0;      ///< nodes that show a mesh
    std::uint64_t vertices = 0;       ///< POSITION elements over all instances
    std::uint64_t targetVertices = 0; ///< morph-target POSITION elements over all instances
    std::uint64_t indices = 0;        ///< index elements (or vertices, without indices)
};

/// The sizes of the scene made of `nodes` (each counted once per listing). An accessor
/// counts with its declared element count when its buffer view could hold that many
/// (without a view: when the accessor reader would allocate them), else 0, since such an
/// accessor is refused with its own message when it is read. Nodes, meshes and accessors
/// that do not exist count 0. Linear in the nodes' primitives.
[[nodiscard]] GltfSceneSize gltfSceneSize(const tinygltf::Model& model, const std::vector<std::size_t>& nodes);

/// The root nodes of the default scene (the first scene when none is named; without
/// scenes, every node that is nobody's child). Throws MeshLoadError naming `name` when the
/// default scene does not exist.
[[nodiscard]] std::vector<int> gltfSceneRoots(const tinygltf::Model& model, const std::string& name);

/// The nodes of the scene whose roots are `roots`, in depth-first pre-order (children in
/// file order): the one walk of a scene's node tree that both glTF readers make. Throws
/// MeshLoadError naming `name` for a node that does not exist or is reached twice (glTF
/// node hierarchies are trees: no cycles, no shared children). Linear in the nodes, with
/// no recursion, for chains of any length.
[[nodiscard]] std::vector<std::size_t> gltfSceneNodes(const tinygltf::Model& model, const std::vector<int>& roots,
                                                      const std::string& name);

} // namespace trimlab
