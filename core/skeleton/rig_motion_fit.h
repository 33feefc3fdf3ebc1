#pragma once
/// \file
/// How well a rig reproduces real motion: the rig extracted from one pose of a captured
/// animation is posed to match every other pose, and the remaining error is measured the
/// way `trimlab skin` measures its own fit (skinning_error.h). It is the rig measure that
/// matters to an animator: a rig whose joints sit where the body does not bend, or whose
/// weights spill across limbs, cannot follow the capture however its bones turn.
///
/// The fit. Each pose's parameters are the rig's own (skeleton_pose.h): a rotation per
/// bone about its head and the root's translation; the rest mesh follows by linear blend
/// skinning with the rig's weights, so nothing is learned from the motion but the
/// rotations. Each pose is fitted by damped Gauss–Newton (Levenberg–Marquardt) on the
/// squared distances Σ_v ‖LBS(v) − v_t‖², starting from the fitted neighbour pose
/// (outwards from the rest pose, which is fitted by the rest pose). An update turns
/// bone a, with everything below it, by a small world rotation ω_a about its posed head
/// p_a; a vertex's skinned position y moves by ω_a × (y − p_a) for every influence below
/// a, so the normal equations need only the 3-vectors Σ w_k (y_k − p_a) per vertex and
/// bone above it. That makes a pose of a 30-bone rig on a 10k-vertex mesh a few
/// milliseconds per iteration. The fit is a local minimiser, so its error bounds the
/// rig's best from above.

#include "core/skeleton/bone_heat_weights.h"
#include "core/skeleton/skeleton.h"
#include "core/skeleton/skeleton_pose.h"
#include "core/skinning/skinning_error.h"
#include "core/util/task_control.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace trimlab {

struct RigMotionFitOptions {
    int maxIterations = 30; ///< Levenberg–Marquardt steps per pose at most
    /// A pose's fit stops when a step lowers its squared error by less than this fraction.
    double tolerance = 1e-4;
};

struct RigMotionFit {
    std::vector<SkeletonPose> poses; ///< #P fitted poses, in the animation's order
    /// The fitted rig's LBS poses against the captured ones; the diagonal is the rest
    /// pose's, as `trimlab skin` reports.
    SkinningError error;
    int iterations = 0; ///< Levenberg–Marquardt steps over all poses
    double milliseconds = 0.0;
};

/// Fits `rig` (with `weights`, #V, on the rest mesh `poses[restPose]`) to every pose of
/// `poses` (#P × #V). Progress stage "motion fit" (poses done of #P). Throws
/// std::invalid_argument when the sizes disagree, restPose ≥ #P or the rig is invalid
/// (requireValidRig); OperationCancelled when asked to stop.
[[nodiscard]] RigMotionFit fitRigToMotion(const SkeletonRig& rig, const BoneWeights& weights,
                                          const std::vector<PosePositions>& poses, std::size_t restPose,
                                          const RigMotionFitOptions& options = {}, const TaskControl& control = {});

/// "E_RMS 2.31 (E_RMS/diagonal 0.91) over 48 poses, fitted in 1.2 s": the line `trimlab
/// skeleton` prints and the Skeleton panel shows.
[[nodiscard]] std::string describeRigMotionFit(const RigMotionFit& fit);

} // namespace trimlab
