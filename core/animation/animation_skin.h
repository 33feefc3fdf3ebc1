#pragma once
/// \file
/// The linear blend skin that posed a glTF animation (glTF 2.0 §3.7.3), kept beside the
/// sampled poses when one skin moves the whole scene and nothing else does (no morph
/// targets, every vertex weighted): pose t of vertex v is Σ_i w_vi · M_{j_vi}(t) · b_v with
/// M_j(t) = world(joint j at t) · inverseBind_j. A renderer can then pose the file on the
/// GPU from the bind positions, weights and per-pose joint matrices instead of uploading
/// every sampled pose; the sampled poses stay the reference.

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace trimlab {

struct AnimationSkin {
    std::size_t jointCount = 0;
    std::size_t influences = 0;                         ///< per vertex (4 per JOINTS_n/WEIGHTS_n set)
    std::vector<glm::dvec3> bindPositions;              ///< #V, mesh space
    std::vector<std::uint32_t> joints;                  ///< #V × influences, indices into the joints
    std::vector<double> weights;                        ///< #V × influences, each vertex's summing to 1
    std::vector<std::vector<glm::dmat4>> jointMatrices; ///< #P × jointCount
};

/// `skin` for the vertices `kept` of its mesh, in that order (after welding).
[[nodiscard]] AnimationSkin keepSkinVertices(const AnimationSkin& skin, const std::vector<std::size_t>& kept);

} // namespace trimlab
