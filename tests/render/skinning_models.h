#pragma once
/// \file
/// Skinned models of shared animations for the GPU skinning test: a few poses of an
/// animation (to fit with core/skinning/seed_bones.h), and models with chosen transforms
/// that stress what fits rarely produce (antipodal dual quaternions, large rotations,
/// eight influences).

#include "core/animation/mesh_animation.h"
#include "core/animation/vertex_graph.h"
#include "core/skinning/skinning_model.h"

#include <cstddef>
#include <string>
#include <vector>

namespace trimlab::test {

/// The poses `keep` (indices into the mesh sequence `source`, a folder or pattern as
/// sequenceFiles takes it; only those files are read) as one animation with rest pose
/// `restPose` (an index into `keep`). Throws what loading throws, std::out_of_range for a
/// pose beyond the sequence.
[[nodiscard]] MeshAnimation selectedPoses(const std::string& source, const std::vector<std::size_t>& keep,
                                          std::size_t restPose);

/// A model on the rest pose of `animation` with `poseCount` poses of random transforms
/// (seeded by `seed`) for `bones` bones placed at nearest-seed centres, each vertex
/// weighted by its `influences` nearest bones (1 … kMaxInfluences). DQS transforms turn
/// up to 150° and every other bone carries the antipodal dual quaternion −q̂, so blends
/// depend on the sign alignment; LBS transforms add scale and shear.
[[nodiscard]] SkinningModel chosenTransformModel(const MeshAnimation& animation, std::size_t bones,
                                                 std::size_t influences, SkinningMethod method, SkinningChain chain,
                                                 std::size_t poseCount, unsigned seed);

} // namespace trimlab::test
