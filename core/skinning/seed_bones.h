#pragma once
/// \file
/// A skinned model fitted without a segmentation run, for benchmarks and tests of the
/// skinning's playback: the cost of a skinned pose and the agreement of the GPU with the
/// CPU depend on the vertex, bone and influence counts, not on where the bones sit, so
/// compact segments around farthest-point seeds stand in for the animation's own
/// segmentation (which takes longer than the fit itself on a large animation).

#include "core/animation/mesh_animation.h"
#include "core/animation/vertex_graph.h"
#include "core/skinning/skinning_model.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace trimlab {

/// `count` seeds by farthest-point sampling from vertex 0, every vertex labelled with its
/// nearest seed (Euclidean, in `positions`): compact segments, every label used when
/// `count` ≤ the number of distinct positions.
[[nodiscard]] VertexLabeling nearestSeedLabels(const std::vector<glm::vec3>& positions, std::size_t count);

/// fitSkinning of `animation` with `bones` bones (nearestSeedLabels of the rest pose, made
/// smooth by the fitter's segmentation weights: at most 4 influences), by `method` along
/// `chain`. Throws what fitSkinning throws.
[[nodiscard]] SkinningModel seedBoneModel(const MeshAnimation& animation, std::size_t bones, SkinningMethod method,
                                          SkinningChain chain);

} // namespace trimlab
