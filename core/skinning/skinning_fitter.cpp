#include "core/skinning/skinning_fitter.h"

#include "core/skinning/skinning_pose_fit.h"
#include "core/skinning/skinning_reconstruction.h"

#include <chrono>

namespace trimlab {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

PoseFitOptions poseOptions(const SkinningFitOptions& options)
{
    PoseFitOptions pose = options.poseFit;
    pose.threads = options.threads;
    return pose;
}

// A model with `weights` fitted to `poses`; adds the time to `fitMs`.
SkinningModel fitModel(const MeshAnimation& animation, const std::vector<PosePositions>& poses,
                       const PosePositions& rest, SkinningWeights weights, const SkinningFitOptions& options,
                       const TaskControl& control, double& fitMs)
{
    const auto start = Clock::now();
    SkinningModel model = identitySkinningModel(options.method, options.chain, animation.poseCount(),
                                                animation.restPose, rest, std::move(weights), animation.triangles);
    fitSkinningTransforms(model, poses, poseOptions(options), control);
    fitMs += msSince(start);
    return model;
}

SkinningError evaluate(const SkinningModel& model, const std::vector<PosePositions>& poses, double& errorMs)
{
    const auto start = Clock::now();
    SkinningError error = measureSkinningError(poses, reconstructPoses(model), model.restPose);
    errorMs += msSince(start);
    return error;
}

void applyWeightCorrections(SkinningFitResult& result, const MeshAnimation& animation,
                            const std::vector<PosePositions>& poses, const SkinningFitOptions& options,
                            const TaskControl& control)
{
    const auto start = Clock::now();
    const VertexGraph graph = buildVertexGraph(animation.vertexCount(), animation.triangles);
    SkinningWeights weights =
        correctedWeights(result.model, poses, graph, {options.neighbourBones, options.threads}, control);
    double ignored = 0.0;
    SkinningModel refit =
        fitModel(animation, poses, result.model.restPositions, std::move(weights), options, control, ignored);
    SkinningError error = evaluate(refit, poses, result.times.errorMs);
    result.times.weightCorrectionMs = msSince(start);
    if (error.eRms <= result.error.eRms) {
        result.model = std::move(refit);
        result.error = std::move(error);
        result.weightCorrectionsKept = true;
    }
}

void applyVertexCorrections(SkinningFitResult& result, const std::vector<PosePositions>& poses,
                            const SkinningFitOptions& options, const TaskControl& control)
{
    const auto start = Clock::now();
    SkinningModel corrected = result.model;
    const std::vector<glm::dvec3> e = restPoseCorrections(corrected, poses, options.threads, control);
    for (std::size_t j = 0; j < e.size(); ++j)
        corrected.restPositions[j] += e[j];
    result.times.vertexCorrectionMs = msSince(start);
    SkinningError error = evaluate(corrected, poses, result.times.errorMs);
    if (error.eRms <= result.error.eRms) {
        result.model = std::move(corrected);
        result.error = std::move(error);
        result.vertexCorrectionsKept = true;
    }
}

} // namespace

SkinningFitResult fitSkinning(const MeshAnimation& animation, SkinningWeights weights,
                              const SkinningFitOptions& options, const TaskControl& control)
{
    const auto start = Clock::now();
    requireWellFormed(animation);
    const std::vector<PosePositions> poses = animationPositions(animation);
    SkinningFitResult result;
    result.model = fitModel(animation, poses, poses[animation.restPose], std::move(weights), options, control,
                            result.times.fitMs);
    result.error = evaluate(result.model, poses, result.times.errorMs);
    result.uncorrectedError = result.error;
    if (options.weightCorrections)
        applyWeightCorrections(result, animation, poses, options, control);
    if (options.vertexCorrections)
        applyVertexCorrections(result, poses, options, control);
    result.times.totalMs = msSince(start);
    return result;
}

SkinningFitResult fitSkinning(const MeshAnimation& animation, const VertexLabeling& segmentation,
                              const SkinningFitOptions& options, const TaskControl& control)
{
    const auto start = Clock::now();
    requireWellFormed(animation);
    const VertexGraph graph = buildVertexGraph(animation.vertexCount(), animation.triangles);
    const PosePositions rest = toDoublePositions(animation.poses[animation.restPose]);
    SkinningWeights weights = segmentationWeights(graph, rest, segmentation, options.weights, control);
    const double weightsMs = msSince(start);
    SkinningFitResult result = fitSkinning(animation, std::move(weights), options, control);
    result.times.weightsMs = weightsMs;
    result.times.totalMs += weightsMs;
    return result;
}

} // namespace trimlab
