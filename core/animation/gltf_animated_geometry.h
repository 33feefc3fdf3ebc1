#pragma once
/// \file
/// The deformable geometry of a glTF 2.0 scene: every triangle primitive of every mesh
/// node, with its morph targets and its skin, posed for given node transforms by morphing
/// and linear blend skinning (glTF 2.0 §3.7.3 and §3.8). Internal to the glTF animation
/// loader.

#include "core/animation/gltf_node_transforms.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace trimlab {

/// A skin: joint nodes and their inverse bind matrices (identity when the file has none).
struct GltfSkin {
    std::vector<std::size_t> joints;
    std::vector<glm::dmat4> inverseBind;
};

/// The joint matrices of `skin` for nodes whose world matrices are `world`:
/// world(joint j) · inverseBind_j, one per joint (glTF 2.0 §3.7.3).
[[nodiscard]] std::vector<glm::dmat4> jointMatrices(const GltfSkin& skin, const std::vector<glm::dmat4>& world);

/// One triangle primitive of one mesh node.
/// - `base`: #v POSITION values (mesh space).
/// - `targets`: per morph target #v POSITION displacements (zeros when absent).
/// - `joints`, `weights`: #v × `influences` skin joints (indices into the skin's joint
///   list) and weights, from JOINTS_n / WEIGHTS_n; empty without a skin.
struct GltfPrimitiveInstance {
    std::size_t node = 0;
    int skin = -1;
    std::vector<glm::dvec3> base;
    std::vector<std::vector<glm::dvec3>> targets;
    std::vector<std::uint32_t> joints;
    std::vector<double> weights;
    std::size_t influences = 0;
};

struct GltfAnimatedGeometry {
    std::vector<GltfPrimitiveInstance> primitives;
    std::vector<GltfSkin> skins;
    std::vector<glm::uvec3> triangles; ///< vertices numbered over the primitives in order
    std::size_t vertexCount = 0;

    /// Scene-space positions (#V) for node transforms `nodes` whose world matrices are
    /// `world`. Morphing first: base + Σ wᵢ·targetᵢ with the node's weights (missing
    /// weights count as 0). Then a skinned primitive is blended with the joint matrices
    /// world(joint)·inverseBind (the mesh node's own transform is ignored, as glTF
    /// requires), weights renormalised to sum 1; a vertex whose weights are all zero, and
    /// every unskinned primitive, takes the mesh node's world matrix.
    [[nodiscard]] std::vector<glm::dvec3> pose(const std::vector<NodeTransform>& nodes,
                                               const std::vector<glm::dmat4>& world) const;
};

/// Reads the mesh nodes of the default scene (else scene 0, else every root node) with
/// `parents` from nodeParents. Primitives of mode TRIANGLES are read; points and lines
/// are skipped. Unskinned nodes whose file world matrix mirrors (negative determinant)
/// get their winding reversed, as in readGltf.
/// Throws MeshLoadError naming the mesh and primitive for: strip and fan primitives
/// (not supported for animation; re-export as triangles), a missing POSITION, morph
/// targets whose count differs between primitives, joints or weights accessors of the
/// wrong shape, joint indices outside the skin, skins with joint nodes that do not exist
/// or a wrong number of inverse bind matrices, every accessor problem
/// (gltf_accessor.h), and a scene without triangles.
[[nodiscard]] GltfAnimatedGeometry readAnimatedGeometry(const tinygltf::Model& model, const std::vector<int>& parents,
                                                        const std::string& name);

} // namespace trimlab
