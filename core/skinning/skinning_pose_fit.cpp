#include "core/skinning/skinning_pose_fit.h"

#include "core/util/parallel_for.h"
#include "core/skinning/skinning_dqs_fit.h"
#include "core/skinning/skinning_lbs_fit.h"
#include "core/skinning/skinning_normal_equations.h"

#include <stdexcept>
#include <string>

namespace trimlab {

SkinningPoseFitter::SkinningPoseFitter(const SkinningWeights& weights, PoseFitOptions options)
    : m_weights(&weights), m_options(options)
{
    requireConvexWeights(weights);
    m_pattern = std::make_shared<const detail::BonePairPattern>(detail::bonePairPattern(weights));
}

void SkinningPoseFitter::fitPose(SkinningModel& model, std::size_t pose, std::span<const glm::dvec3> source,
                                 std::span<const glm::dvec3> target) const
{
    if (model.method == SkinningMethod::Lbs)
        model.affine.at(pose) = detail::fitAffineBoneTransforms(source, target, *m_weights, *m_pattern, m_options);
    else
        model.rigid.at(pose) = detail::fitRigidBoneTransforms(source, target, *m_weights, *m_pattern, {}, m_options);
}

namespace {

void requireMatchingPoses(const SkinningModel& model, const std::vector<PosePositions>& poses)
{
    if (poses.size() != model.poseCount())
        throw std::invalid_argument("skinning fit: " + std::to_string(poses.size()) + " poses for a model of " +
                                    std::to_string(model.poseCount()));
    for (std::size_t t = 0; t < poses.size(); ++t)
        if (poses[t].size() != model.vertexCount())
            throw std::invalid_argument("skinning fit: pose " + std::to_string(t) + " has " +
                                        std::to_string(poses[t].size()) + " vertices, the model " +
                                        std::to_string(model.vertexCount()));
}

void fitPoseToPoseChain(SkinningModel& model, const std::vector<PosePositions>& poses, const SkinningPoseFitter& fitter,
                        const TaskControl& control)
{
    const std::vector<std::size_t> order = chainOrder(model.poseCount(), model.restPose);
    PosePositions previous;
    PosePositions current;
    control.report("fit", 0, order.size() - 1);
    for (std::size_t i = 1; i < order.size(); ++i) {
        control.throwIfCancelled();
        const std::size_t t = order[i];
        if (model.previousPose(t) == model.restPose)
            previous = model.restPositions; // the start of a branch of the chain
        fitter.fitPose(model, t, previous, poses[t]);
        current.resize(previous.size());
        for (std::size_t j = 0; j < current.size(); ++j)
            current[j] = blendedTransform(model, t, j).apply(previous[j]);
        std::swap(previous, current);
        control.report("fit", i, order.size() - 1);
    }
}

} // namespace

void fitSkinningTransforms(SkinningModel& model, const std::vector<PosePositions>& poses, const PoseFitOptions& options,
                           const TaskControl& control)
{
    requireMatchingPoses(model, poses);
    if (model.chain == SkinningChain::PoseToPose) {
        const SkinningPoseFitter fitter(model.weights, options);
        fitPoseToPoseChain(model, poses, fitter, control);
        return;
    }
    PoseFitOptions single = options;
    single.threads = 1; // the poses are the parallel items
    const SkinningPoseFitter fitter(model.weights, single);
    parallelFor(
        model.poseCount(), options.threads,
        [&](std::size_t t) {
            if (t != model.restPose)
                fitter.fitPose(model, t, model.restPositions, poses[t]);
        },
        control, "fit");
}

} // namespace trimlab
