#pragma once
/// \file
/// Fitting the per-pose bone transforms of a whole animation (thesis 4.1.1): pose-to-pose
/// (eq. 4.7 / 4.8, fitted pose after pose) or classical rest-to-pose, with LBS or DQS.

#include "core/skinning/skinning_fit_options.h"
#include "core/skinning/skinning_model.h"
#include "core/skinning/skinning_reconstruction.h"
#include "core/util/task_control.h"

#include <memory>
#include <span>
#include <vector>

namespace trimlab {

namespace detail {
struct BonePairPattern;
}

/// Fits one pose at a time for a fixed weight set; the bone-pair pattern of the weights is
/// computed once (construction is O(#V log B)).
class SkinningPoseFitter {
public:
    /// Throws std::invalid_argument when `weights` are not convex (requireConvexWeights).
    SkinningPoseFitter(const SkinningWeights& weights, PoseFitOptions options);

    /// Replaces the transforms of pose `pose` of `model` (which must have this fitter's
    /// weights) by those that carry `source` onto `target` (#V each): fitAffineBoneTransforms
    /// for LBS, fitRigidBoneTransforms (from the Kabsch start) for DQS.
    void fitPose(SkinningModel& model, std::size_t pose, std::span<const glm::dvec3> source,
                 std::span<const glm::dvec3> target) const;

    [[nodiscard]] const PoseFitOptions& options() const { return m_options; }

private:
    const SkinningWeights* m_weights;
    PoseFitOptions m_options;
    std::shared_ptr<const detail::BonePairPattern> m_pattern;
};

/// Fits the transforms of every pose but the rest pose of `model`, whose rest positions,
/// weights, method and chain are already set, to the original poses `poses` (#P × #V):
/// - PoseToPose: in chainOrder, pose t from the *reconstructed* pose previousPose(t) (not
///   the original one): the fit then sees exactly what eq. 4.7 / 4.8 will apply its
///   transforms to, so an approximation error made at one pose is corrected at the next
///   instead of accumulating along the chain. Poses are sequential; the per-pose work uses
///   options.threads.
/// - RestToPose: every pose from the rest positions (the classical fit, for comparison),
///   poses in parallel.
/// Progress stage "fit", one item per pose; cancellable between poses (OperationCancelled,
/// `model` is then left partly fitted — callers work on a copy). Throws
/// std::invalid_argument when `poses` does not match the model's size.
void fitSkinningTransforms(SkinningModel& model, const std::vector<PosePositions>& poses, const PoseFitOptions& options,
                           const TaskControl& control = {});

} // namespace trimlab
