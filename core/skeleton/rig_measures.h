#pragma once
/// \file
/// What an animator asks of a rig before posing it, beside the evaluator's containment,
/// centring and coverage (skeleton_evaluation.h): how many joints it has, how many bones
/// leave the root (a pelvis has three or four: the spine, the legs and a tail; a hub
/// with eight makes the legs siblings of the arms), whether a bone turns back on its
/// parent (beyond 120° nobody can tell which way the joint bends), and whether the
/// weights stay in their limb.
///
/// Weight leakage: each vertex belongs to the region of one joint (SkeletonRig::
/// vertexJoint). The bones around it are the bones that end at that joint or at one of
/// its neighbours in the joint tree; any weight a vertex gives to another bone has
/// crossed at least one whole bone of the body (a thigh moved by the tail, a hand by
/// the other hand). The leakage is that weight's share of all weight, and the share of
/// vertices that give such a bone more than a quarter of their weight.

#include "core/skeleton/bone_heat_weights.h"
#include "core/skeleton/skeleton.h"

#include <string>

namespace trimlab {

struct RigMeasures {
    int joints = 0;
    int rootBones = 0;                ///< bones whose head is the root joint
    int turnBacks = 0;                ///< bones turning back on their parent bone by more than 120°
    double sharpestTurnDegrees = 0.0; ///< the largest angle between a bone and its parent bone
    double leakedWeight = 0.0;        ///< share of all weight on bones away from the vertex (see above)
    double leakingVertices = 0.0;     ///< share of vertices giving such bones more than 1/4
};

/// A bone turns back on its parent when the angle between their directions exceeds this.
inline constexpr double kTurnBackDegrees = 120.0;

/// The measures of `rig` with `weights` over its vertices (rig.vertexJoint and weights
/// describe the same mesh). Throws std::invalid_argument if their vertex counts differ or
/// a weight names a bone the rig does not have.
[[nodiscard]] RigMeasures measureRig(const SkeletonRig& rig, const BoneWeights& weights);

/// One line for people: "30 joints, 3 bones at the root, 0 turn-backs beyond 120°
/// (sharpest 97°), weight leakage 0.4 % (0.1 % of vertices)".
[[nodiscard]] std::string describeRigMeasures(const RigMeasures& measures);

} // namespace trimlab
