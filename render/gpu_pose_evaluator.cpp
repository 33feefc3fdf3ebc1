#include "render/gpu_pose_evaluator.h"

#include "render/frame/gpu_skinning.h"
#include "render/frame/gpu_subdivision.h"

#include <stdexcept>

namespace trimlab::render {

namespace {

template <class Pose>
const Pose& poseOf(const ShownPose& pose)
{
    const Pose* typed = std::get_if<Pose>(&pose.evaluation);
    if (!typed)
        throw std::invalid_argument("GpuPoseEvaluator: a pose of another kind than its evaluator's.");
    return *typed;
}

class SkinningEvaluator final : public GpuPoseEvaluator {
public:
    SkinningEvaluator(GlFunctions& gl, const SkinningModel& model) : m_skinning(gl, model) {}
    void evaluate(GpuScene& scene, std::size_t object, const ShownPose& pose) override
    {
        m_skinning.skinPose(scene, object, poseOf<SkinnedPose>(pose).pose);
    }
    [[nodiscard]] PoseEvaluation kind() const override { return PoseEvaluation::GpuSkinning; }

private:
    GpuSkinning m_skinning;
};

class SubdivisionEvaluator final : public GpuPoseEvaluator {
public:
    SubdivisionEvaluator(GlFunctions& gl, const SubdivisionStencils& stencils) : m_subdivision(gl, stencils) {}
    void evaluate(GpuScene& scene, std::size_t object, const ShownPose& pose) override
    {
        m_subdivision.evaluate(scene, object, poseOf<SubdivisionPose>(pose).controlPoints);
    }
    [[nodiscard]] PoseEvaluation kind() const override { return PoseEvaluation::GpuSubdivision; }

private:
    GpuSubdivision m_subdivision;
};

} // namespace

std::shared_ptr<const void> gpuPoseSource(const ShownPose& pose)
{
    if (const auto* skinned = std::get_if<SkinnedPose>(&pose.evaluation))
        return skinned->model;
    if (const auto* surface = std::get_if<SubdivisionPose>(&pose.evaluation))
        return surface->stencils;
    return nullptr;
}

std::unique_ptr<GpuPoseEvaluator> makeGpuPoseEvaluator(GlFunctions& gl, const ShownPose& pose)
{
    if (const auto* skinned = std::get_if<SkinnedPose>(&pose.evaluation))
        return std::make_unique<SkinningEvaluator>(gl, *skinned->model);
    if (const auto* surface = std::get_if<SubdivisionPose>(&pose.evaluation))
        return std::make_unique<SubdivisionEvaluator>(gl, *surface->stencils);
    return nullptr;
}

} // namespace trimlab::render
