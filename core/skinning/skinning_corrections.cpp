#include "core/skinning/skinning_corrections.h"

#include "core/skinning/convex_vertex_weights.h"
#include "core/util/parallel_for.h"
#include "core/skinning/skinning_normal_equations.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace trimlab {

namespace {

glm::dvec3 vertexCorrection(const SkinningModel& model, const std::vector<PosePositions>& poses, std::size_t j,
                            std::vector<Affine3>& transforms)
{
    vertexRestToPose(model, j, transforms);
    glm::dmat3 normal(0.0);
    glm::dvec3 rhs(0.0);
    for (std::size_t t = 0; t < transforms.size(); ++t) {
        const glm::dmat3& n = transforms[t].linear;
        normal += glm::transpose(n) * n;
        rhs += glm::transpose(n) * (poses[t][j] - transforms[t].apply(model.restPositions[j]));
    }
    return glm::inverse(normal) * rhs;
}

// Bone b's transform at pose t as a matrix (LBS: Q_b^t; DQS: the rigid matrix of Q̂_b^t).
Affine3 boneMatrix(const SkinningModel& model, std::size_t t, std::uint32_t b)
{
    return model.method == SkinningMethod::Lbs ? model.affine[t][b] : toAffine(model.rigid[t][b]);
}

std::vector<std::uint32_t> candidateBones(const SkinningModel& model, const VertexGraph& graph, std::size_t j,
                                          bool neighbours)
{
    std::vector<std::uint32_t> bones;
    const auto addOf = [&](std::size_t v) {
        const VertexInfluences& in = model.weights.vertices[v];
        bones.insert(bones.end(), in.bones.begin(), in.bones.begin() + in.count);
    };
    addOf(j);
    if (neighbours && j < graph.vertexCount())
        for (std::uint32_t n : graph.neighborsOf(j))
            addOf(n);
    std::sort(bones.begin(), bones.end());
    bones.erase(std::unique(bones.begin(), bones.end()), bones.end());
    return bones;
}

// Gram matrix of the difference columns Q_b^t 𝐯^{t−1} − 𝐯^t over every pose but the rest pose.
Eigen::MatrixXd differenceGram(const SkinningModel& model, const std::vector<PosePositions>& poses, std::size_t j,
                               const std::vector<std::uint32_t>& bones)
{
    const Eigen::Index m = Eigen::Index(bones.size());
    Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(m, m);
    Eigen::MatrixXd columns(3, m);
    for (std::size_t t = 0; t < poses.size(); ++t) {
        if (t == model.restPose)
            continue;
        const glm::dvec3& previous = poses[model.previousPose(t)][j];
        for (Eigen::Index c = 0; c < m; ++c) {
            const glm::dvec3 d = boneMatrix(model, t, bones[std::size_t(c)]).apply(previous) - poses[t][j];
            columns.col(c) = Eigen::Vector3d(d.x, d.y, d.z);
        }
        gram.noalias() += columns.transpose() * columns;
    }
    return gram;
}

VertexInfluences correctVertexWeights(const SkinningModel& model, const std::vector<PosePositions>& poses,
                                      const VertexGraph& graph, std::size_t j, bool neighbours, std::size_t limit)
{
    const VertexInfluences& old = model.weights.vertices[j];
    const std::vector<std::uint32_t> bones = candidateBones(model, graph, j, neighbours);
    const Eigen::MatrixXd gram = differenceGram(model, poses, j, bones);
    return bestConvexInfluences(gram, bones, old, limit);
}

} // namespace

std::vector<glm::dvec3> restPoseCorrections(const SkinningModel& model, const std::vector<PosePositions>& poses,
                                            unsigned threads, const TaskControl& control)
{
    std::vector<glm::dvec3> corrections(model.vertexCount(), glm::dvec3(0.0));
    const std::size_t chunks = detail::chunkCount(model.vertexCount());
    parallelFor(
        chunks, threads,
        [&](std::size_t c) {
            std::vector<Affine3> transforms;
            const auto [begin, end] = detail::chunkRange(model.vertexCount(), c);
            for (std::size_t j = begin; j < end; ++j)
                corrections[j] = vertexCorrection(model, poses, j, transforms);
        },
        control, "vertex corrections");
    return corrections;
}

SkinningWeights correctedWeights(const SkinningModel& model, const std::vector<PosePositions>& poses,
                                 const VertexGraph& graph, const WeightCorrectionOptions& options,
                                 const TaskControl& control)
{
    SkinningWeights result = model.weights;
    const std::size_t chunks = detail::chunkCount(model.vertexCount());
    parallelFor(
        chunks, options.threads,
        [&](std::size_t c) {
            const auto [begin, end] = detail::chunkRange(model.vertexCount(), c);
            for (std::size_t j = begin; j < end; ++j)
                result.vertices[j] =
                    correctVertexWeights(model, poses, graph, j, options.neighbourBones, options.limit);
        },
        control, "weight corrections");
    return result;
}

} // namespace trimlab
