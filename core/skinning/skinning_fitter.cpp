#include "core/skinning/skinning_fitter.h"

#include "core/skinning/skinning_pose_fit.h"
#include "core/skinning/skinning_reconstruction.h"

#include <chrono>
#include <cmath>

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
        correctedWeights(result.model, poses, graph,
                         {options.neighbourBones, options.threads, options.decomposition.maxInfluences}, control);
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

// The decomposition's weight and rest updates are the corrections; they are part of the
// descent (each block lowers the error or changes nothing), so they are always kept.
SkinningFitResult fitDecomposition(const MeshAnimation& animation, const std::vector<PosePositions>& poses,
                                   SkinningWeights weights, const SkinningFitOptions& options,
                                   const TaskControl& control)
{
    SkinningFitResult result;
    const auto start = Clock::now();
    SkinningDecompositionOptions decomposition = options.decomposition;
    decomposition.rigidJoints = options.fitExported;
    decomposition.updateWeights = options.weightCorrections;
    decomposition.updateRestPositions = options.vertexCorrections;
    decomposition.threads = options.threads;
    const VertexGraph graph = buildVertexGraph(animation.vertexCount(), animation.triangles);
    const SkinningDecomposition d = decomposeSkinning(poses, animation.restPose, poses[animation.restPose],
                                                      std::move(weights), graph, decomposition, control);
    result.model = decomposedSkinningModel(d, animation.restPose, animation.triangles);
    result.times.fitMs = msSince(start);
    result.error = evaluate(result.model, poses, result.times.errorMs);
    result.uncorrectedError.eRms = d.firstFitERms;
    result.uncorrectedError.diagonal = result.error.diagonal;
    result.uncorrectedError.eRmsDiagonal = result.error.diagonal > 0.0 ? d.firstFitERms / result.error.diagonal : 0.0;
    result.uncorrectedError.rmse = d.firstFitERms * std::sqrt(3.0) / 1000.0;
    result.weightCorrectionsKept = options.weightCorrections;
    result.vertexCorrectionsKept = options.vertexCorrections;
    result.iterations = d.iterations;
    return result;
}

} // namespace

bool usesDecomposition(const SkinningFitOptions& options)
{
    return options.fitExported ||
           (options.method == SkinningMethod::Lbs && options.chain == SkinningChain::RestToPose &&
            (options.weightCorrections || options.vertexCorrections));
}

SkinningFitResult fitSkinning(const MeshAnimation& animation, SkinningWeights weights,
                              const SkinningFitOptions& options, const TaskControl& control)
{
    const auto start = Clock::now();
    requireWellFormed(animation);
    const std::vector<PosePositions> poses = animationPositions(animation);
    weights = limitedInfluences(std::move(weights), options.decomposition.maxInfluences);
    if (usesDecomposition(options)) {
        SkinningFitResult result = fitDecomposition(animation, poses, std::move(weights), options, control);
        result.times.totalMs = msSince(start);
        return result;
    }
    SkinningFitResult result;
    result.model =
        fitModel(animation, poses, poses[animation.restPose], std::move(weights), options, control, result.times.fitMs);
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
