#pragma once
/// \file
/// A skinned approximation of a mesh animation (thesis 2.3 and chapter 4): the rest pose,
/// B proxy bones with sparse convex vertex weights, and per pose the bone transforms —
/// affine matrices Q_b^t for linear blend skinning (LBS, eq. 4.7) or unit dual quaternions
/// Q̂_b^t for dual quaternion skinning (DQS, eq. 4.8). The same model holds the thesis's
/// pose-to-pose representation (p2p-skinning: Q^t maps pose t−1 to pose t) and the
/// classical rest-to-pose one (M^t maps the rest pose to pose t), told apart by `chain`.
/// Evaluation lives in skinning_reconstruction.h.

#include "core/skinning/dual_quaternion.h"
#include "core/skinning/skinning_affine.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace trimlab {

/// At most this many bones influence a vertex: a glTF skin carries them as JOINTS_0/
/// WEIGHTS_0 and JOINTS_1/WEIGHTS_1. Fits use kDefaultInfluences unless asked for more.
inline constexpr std::size_t kMaxInfluences = 8;

/// The usual limit (thesis 2.3: "l = 4 influences per vertex are adequate"): what every
/// engine and GPU skinning shader plays, JOINTS_0 alone.
inline constexpr std::size_t kDefaultInfluences = 4;

/// The influences of one vertex: `count` ≤ kMaxInfluences pairs (bone, weight), sorted by
/// decreasing weight (ties by bone index); entries past `count` are bone 0, weight 0.
struct VertexInfluences {
    std::array<std::uint32_t, kMaxInfluences> bones{};
    std::array<double, kMaxInfluences> weights{};
    std::uint32_t count = 0;

    bool operator==(const VertexInfluences&) const = default;
};

/// The bone-vertex weights w_{b,j}: #V VertexInfluences over `boneCount` bones. A valid
/// set is convex (weights ≥ 0, summing to 1 per vertex; thesis 2.3) with bone < boneCount.
struct SkinningWeights {
    std::size_t boneCount = 0;
    std::vector<VertexInfluences> vertices;

    bool operator==(const SkinningWeights&) const = default;
};

/// Throws std::invalid_argument naming the first vertex that has no influence, more than
/// kMaxInfluences, a bone ≥ boneCount, a negative or non-finite weight, or weights whose
/// sum differs from 1 by more than `tolerance`.
void requireConvexWeights(const SkinningWeights& weights, double tolerance = 1e-9);

/// Sorts `influences` by decreasing weight (ties: smaller bone first), keeps the `limit`
/// (1 … kMaxInfluences) largest positive ones and rescales them to sum 1. Used wherever
/// dense or candidate weights are made sparse. All-zero input keeps `fallbackBone` with
/// weight 1.
[[nodiscard]] VertexInfluences sparseInfluences(std::vector<std::pair<std::uint32_t, double>> influences,
                                                std::uint32_t fallbackBone, std::size_t limit = kDefaultInfluences);

/// `weights` with every vertex cut to its `limit` (1 … kMaxInfluences) largest influences,
/// rescaled to sum 1 (sparseInfluences); vertices within the limit are unchanged.
[[nodiscard]] SkinningWeights limitedInfluences(SkinningWeights weights, std::size_t limit);

enum class SkinningMethod {
    Lbs, ///< linear blend skinning with affine bone transforms (eq. 2.4, 4.7)
    Dqs, ///< dual quaternion skinning with rigid bone transforms (eq. 2.5, 4.8)
};

enum class SkinningChain {
    PoseToPose, ///< p2p-skinning (4.1.1): transforms[t] map pose previousPose(t) to pose t
    RestToPose, ///< classical skinning (2.3): transforms[t] map the rest pose to pose t
};

/// The skinned animation. Shapes: #V vertices, #P poses, B = weights.boneCount bones.
/// - `restPositions`: #V rest-pose positions v^0 (the animation's rest pose, plus the
///   rest-pose corrections e^V of eq. 4.12 once applied).
/// - `affine` (LBS): #P × B matrices; `rigid` (DQS): #P × B unit dual quaternions. Exactly
///   one of them is filled, as `method` says. The entry of the rest pose is the identity,
///   except in a rest-to-pose LBS model whose rest positions are a bind pose fitted for
///   all poses (the skinning decomposition): its rest-pose matrices then carry the bind
///   pose to the rest pose like any other pose's (restPoseMoves).
/// - `restPose`: the pose the chain starts from. In the thesis it is p_0; here any pose:
///   the p2p chain runs rest → rest+1 → … → #P−1 and rest → rest−1 → … → 0.
struct SkinningModel {
    SkinningMethod method = SkinningMethod::Lbs;
    SkinningChain chain = SkinningChain::PoseToPose;
    std::size_t restPose = 0;
    std::vector<glm::uvec3> triangles;
    std::vector<glm::dvec3> restPositions;
    SkinningWeights weights;
    std::vector<std::vector<Affine3>> affine;
    std::vector<std::vector<DualQuaternion>> rigid;

    [[nodiscard]] std::size_t vertexCount() const { return restPositions.size(); }
    [[nodiscard]] std::size_t boneCount() const { return weights.boneCount; }
    [[nodiscard]] std::size_t poseCount() const { return method == SkinningMethod::Lbs ? affine.size() : rigid.size(); }
    /// The pose whose vertices transforms[pose] act on (t−1 in eq. 4.7 for poses after the
    /// rest pose, t+1 before it; the rest pose for RestToPose and for the rest pose itself).
    [[nodiscard]] std::size_t previousPose(std::size_t pose) const;
};

/// Whether the rest pose has transforms of its own (see `affine` above): a rest-to-pose LBS
/// model with a rest-pose matrix that is not the identity.
[[nodiscard]] bool restPoseMoves(const SkinningModel& model);

/// Every pose once, each after its previousPose: the rest pose, then rest+1 … #P−1, then
/// rest−1 … 0.
[[nodiscard]] std::vector<std::size_t> chainOrder(std::size_t poseCount, std::size_t restPose);

/// A model with `poseCount` poses of identity transforms for `method`, the given rest
/// positions, weights and triangles. Throws std::invalid_argument when the weights are not
/// convex (requireConvexWeights) or not one per rest position, or restPose ≥ poseCount.
[[nodiscard]] SkinningModel identitySkinningModel(SkinningMethod method, SkinningChain chain, std::size_t poseCount,
                                                  std::size_t restPose, std::vector<glm::dvec3> restPositions,
                                                  SkinningWeights weights, std::vector<glm::uvec3> triangles);

} // namespace trimlab
