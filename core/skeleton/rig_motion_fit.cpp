#include "core/skeleton/rig_motion_fit.h"

#include "core/skeleton/rig_validation.h"
#include "core/skinning/dual_quaternion.h"
#include "core/skinning/skinning_affine.h"
#include "core/util/parallel_for.h"

#include <Eigen/Dense>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>

namespace trimlab {

namespace {

// One vertex's influences with weights that sum to 1, and the bones whose rotation moves
// it: every influence and every bone above one, each with the influences below it.
struct VertexInfluences {
    std::array<int, kBoneInfluences> bones{};
    std::array<double, kBoneInfluences> weights{};
    std::size_t count = 0;
    std::size_t firstMover = 0, moverCount = 0; ///< range in MotionModel::movers / masks
};

struct MotionModel {
    std::vector<glm::dvec3> rest;
    std::vector<VertexInfluences> vertices;
    std::vector<int> movers;         ///< bone indices, parents first within a vertex
    std::vector<std::uint8_t> masks; ///< the influences (bits) below each mover
    std::size_t boneCount = 0;
    [[nodiscard]] std::size_t unknowns() const { return 3 * boneCount + 3; }
};

VertexInfluences influencesOf(const BoneWeights& weights, std::size_t v)
{
    VertexInfluences in;
    double total = 0.0;
    for (std::size_t k = 0; k < kBoneInfluences; ++k)
        if (weights.bones[v][k] >= 0 && weights.weights[v][k] > 0.0f) {
            in.bones[in.count] = weights.bones[v][k];
            in.weights[in.count++] = double(weights.weights[v][k]);
            total += double(weights.weights[v][k]);
        }
    for (std::size_t k = 0; k < in.count; ++k)
        in.weights[k] /= total;
    return in;
}

MotionModel motionModel(const SkeletonRig& rig, const BoneWeights& weights, const PosePositions& rest)
{
    MotionModel model;
    model.rest = rest;
    model.boneCount = rig.bones.size();
    model.vertices.reserve(rest.size());
    std::vector<std::uint8_t> below(rig.bones.size(), 0);
    for (std::size_t v = 0; v < rest.size(); ++v) {
        VertexInfluences in = influencesOf(weights, v);
        std::fill(below.begin(), below.end(), std::uint8_t(0));
        for (std::size_t k = 0; k < in.count; ++k)
            for (int b = in.bones[k]; b >= 0; b = rig.bones[std::size_t(b)].parentBone)
                below[std::size_t(b)] |= std::uint8_t(1u << k);
        in.firstMover = model.movers.size();
        for (std::size_t b = 0; b < below.size(); ++b)
            if (below[b] != 0) {
                model.movers.push_back(int(b));
                model.masks.push_back(below[b]);
            }
        in.moverCount = model.movers.size() - in.firstMover;
        model.vertices.push_back(in);
    }
    return model;
}

// The posed bones of one pose: each bone's rigid motion as a matrix and its posed head.
struct PosedBones {
    std::vector<DualQuaternion> motions;
    std::vector<Affine3> matrices;
    std::vector<glm::dvec3> heads;
};

PosedBones posedBones(const SkeletonRig& rig, const SkeletonPose& pose)
{
    PosedBones posed;
    posed.motions = boneMotions(rig, pose);
    for (std::size_t b = 0; b < rig.bones.size(); ++b) {
        posed.matrices.push_back(toAffine(posed.motions[b]));
        posed.heads.push_back(posed.matrices.back().apply(rig.joints[std::size_t(rig.bones[b].head)]));
    }
    return posed;
}

// y_k of every influence, and the blended position.
glm::dvec3 skinnedVertex(const MotionModel& model, std::size_t v, const PosedBones& posed,
                         std::array<glm::dvec3, kBoneInfluences>& y)
{
    const VertexInfluences& in = model.vertices[v];
    if (in.count == 0)
        return model.rest[v];
    glm::dvec3 p(0.0);
    for (std::size_t k = 0; k < in.count; ++k) {
        y[k] = posed.matrices[std::size_t(in.bones[k])].apply(model.rest[v]);
        p += in.weights[k] * y[k];
    }
    return p;
}

// Vertices per parallel block of the fit's sums: a few blocks on a 10k-vertex mesh,
// each summed in a fixed order and the blocks added in order, so results do not depend
// on the thread count.
constexpr std::size_t kFitBlock = 2048;

std::size_t blockCount(const MotionModel& model)
{
    return (model.vertices.size() + kFitBlock - 1) / kFitBlock;
}

double squaredError(const MotionModel& model, const PosedBones& posed, const PosePositions& target)
{
    std::vector<double> sums(blockCount(model), 0.0);
    parallelFor(sums.size(), 0, [&](std::size_t block) {
        std::array<glm::dvec3, kBoneInfluences> y;
        const std::size_t end = std::min(model.vertices.size(), (block + 1) * kFitBlock);
        for (std::size_t v = block * kFitBlock; v < end; ++v) {
            const glm::dvec3 r = skinnedVertex(model, v, posed, y) - target[v];
            sums[block] += glm::dot(r, r);
        }
    });
    double sum = 0.0;
    for (const double s : sums)
        sum += s;
    return sum;
}

struct NormalEquations {
    Eigen::MatrixXd h;
    Eigen::VectorXd g;
};

// Adds J_aᵀ J_b = (a·b)I − b aᵀ at (row, col), and its transpose at (col, row).
void addRotationBlock(Eigen::MatrixXd& h, std::size_t row, std::size_t col, const glm::dvec3& a, const glm::dvec3& b)
{
    const double ab = glm::dot(a, b);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const double value = (i == j ? ab : 0.0) - b[i] * a[j];
            h(Eigen::Index(row) + i, Eigen::Index(col) + j) += value;
            if (row != col)
                h(Eigen::Index(col) + j, Eigen::Index(row) + i) += value;
        }
}

// [c]× at (row, t) and its transpose [c]×ᵀ at (t, row): J_aᵀ J_t with J_t = I.
void addTranslationBlock(Eigen::MatrixXd& h, std::size_t row, std::size_t t, const glm::dvec3& c)
{
    const double m[3][3] = {{0.0, -c.z, c.y}, {c.z, 0.0, -c.x}, {-c.y, c.x, 0.0}};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            h(Eigen::Index(row) + i, Eigen::Index(t) + j) += m[i][j];
            h(Eigen::Index(t) + j, Eigen::Index(row) + i) += m[i][j];
        }
}

// Adds vertex v's rows to the normal equations: J_a = −[c_a]× for each bone a above one
// of its influences, with c_a = Σ_{k below a} w_k (y_k − p_a), and J_t = I for the root's
// translation (its diagonal block is added once per block, see normalEquations).
void addVertexRows(const MotionModel& model, std::size_t v, const PosedBones& posed, const PosePositions& target,
                   NormalEquations& eq, std::vector<glm::dvec3>& c)
{
    const VertexInfluences& in = model.vertices[v];
    const std::size_t t = 3 * model.boneCount;
    std::array<glm::dvec3, kBoneInfluences> y;
    const glm::dvec3 r = skinnedVertex(model, v, posed, y) - target[v];
    c.resize(in.moverCount);
    for (std::size_t m = 0; m < in.moverCount; ++m) {
        const std::size_t bone = std::size_t(model.movers[in.firstMover + m]);
        const std::uint8_t mask = model.masks[in.firstMover + m];
        glm::dvec3 sum(0.0);
        for (std::size_t k = 0; k < in.count; ++k)
            if (mask & (1u << k))
                sum += in.weights[k] * (y[k] - posed.heads[bone]);
        c[m] = sum;
        const glm::dvec3 gradient = glm::cross(sum, r);
        for (int i = 0; i < 3; ++i)
            eq.g(Eigen::Index(3 * bone) + i) += gradient[i];
    }
    for (std::size_t m = 0; m < in.moverCount; ++m) {
        const std::size_t row = 3 * std::size_t(model.movers[in.firstMover + m]);
        for (std::size_t l = m; l < in.moverCount; ++l)
            addRotationBlock(eq.h, row, 3 * std::size_t(model.movers[in.firstMover + l]), c[m], c[l]);
        addTranslationBlock(eq.h, row, t, c[m]);
    }
    for (int i = 0; i < 3; ++i)
        eq.g(Eigen::Index(t) + i) += r[i];
}

// Jᵀ J and Jᵀ r of the pose, summed per block of vertices in parallel.
NormalEquations normalEquations(const MotionModel& model, const PosedBones& posed, const PosePositions& target)
{
    const Eigen::Index n = Eigen::Index(model.unknowns());
    const auto zero = [n] { return NormalEquations{Eigen::MatrixXd::Zero(n, n), Eigen::VectorXd::Zero(n)}; };
    std::vector<NormalEquations> blocks(blockCount(model));
    parallelFor(blocks.size(), 0, [&](std::size_t block) {
        NormalEquations eq = zero();
        std::vector<glm::dvec3> c;
        double skinned = 0.0;
        const std::size_t end = std::min(model.vertices.size(), (block + 1) * kFitBlock);
        for (std::size_t v = block * kFitBlock; v < end; ++v)
            if (model.vertices[v].count > 0) {
                addVertexRows(model, v, posed, target, eq, c);
                skinned += 1.0;
            }
        for (Eigen::Index i = n - 3; i < n; ++i)
            eq.h(i, i) += skinned;
        blocks[block] = std::move(eq);
    });
    NormalEquations sum = zero();
    for (const NormalEquations& eq : blocks) {
        sum.h += eq.h;
        sum.g += eq.g;
    }
    return sum;
}

// The pose after the step: bone b turned by exp(ω_b) in world axes about its posed head,
// which in its rest-pose axes is conj(q_P)·exp(ω_b)·q_P·q_b (q_P the rotation of the
// parent's motion), and the root moved by δt.
SkeletonPose steppedPose(const SkeletonRig& rig, const SkeletonPose& pose, const PosedBones& posed,
                         const Eigen::VectorXd& step)
{
    SkeletonPose next = pose;
    for (std::size_t b = 0; b < rig.bones.size(); ++b) {
        const glm::dvec3 omega(step(Eigen::Index(3 * b)), step(Eigen::Index(3 * b + 1)), step(Eigen::Index(3 * b + 2)));
        const double angle = glm::length(omega);
        if (!(angle > 0.0))
            continue;
        const int parent = rig.bones[b].parentBone;
        const glm::dquat qp =
            parent < 0 ? glm::dquat(1.0, 0.0, 0.0, 0.0) : glm::normalize(posed.motions[std::size_t(parent)].real);
        const glm::dquat turn = glm::angleAxis(angle, omega / angle);
        next.rotations[b] = glm::normalize(glm::conjugate(qp) * turn * qp * glm::normalize(pose.rotations[b]));
    }
    const Eigen::Index t = Eigen::Index(3 * rig.bones.size());
    next.rootTranslation += glm::dvec3(step(t), step(t + 1), step(t + 2));
    return next;
}

// Levenberg–Marquardt from `pose` towards `target`; returns the steps taken.
int fitPose(const SkeletonRig& rig, const MotionModel& model, const PosePositions& target, SkeletonPose& pose,
            const RigMotionFitOptions& options)
{
    PosedBones posed = posedBones(rig, pose);
    double error = squaredError(model, posed, target);
    double damping = 1e-3;
    int steps = 0;
    for (int iteration = 0; iteration < options.maxIterations && error > 0.0; ++iteration) {
        ++steps;
        const NormalEquations eq = normalEquations(model, posed, target);
        const double floor = std::max(1e-12, 1e-9 * eq.h.diagonal().maxCoeff());
        bool improved = false;
        while (!improved && damping < 1e10) {
            Eigen::MatrixXd damped = eq.h;
            for (Eigen::Index i = 0; i < damped.rows(); ++i)
                damped(i, i) += damping * std::max(eq.h(i, i), floor);
            const Eigen::VectorXd step = damped.ldlt().solve(-eq.g);
            SkeletonPose trial = steppedPose(rig, pose, posed, step);
            PosedBones trialPosed = posedBones(rig, trial);
            const double trialError = squaredError(model, trialPosed, target);
            if (trialError < error) {
                const double gain = (error - trialError) / error;
                pose = std::move(trial);
                posed = std::move(trialPosed);
                error = trialError;
                damping = std::max(damping / 3.0, 1e-9);
                improved = true;
                if (gain < options.tolerance)
                    return steps;
            } else {
                damping *= 4.0;
            }
        }
        if (!improved)
            break;
    }
    return steps;
}

void requireFittable(const SkeletonRig& rig, const BoneWeights& weights, const std::vector<PosePositions>& poses,
                     std::size_t restPose)
{
    requireValidRig(rig, "motion fit");
    if (restPose >= poses.size())
        throw std::invalid_argument("motion fit: the rest pose " + std::to_string(restPose) + " is not one of the " +
                                    std::to_string(poses.size()) + " poses");
    for (std::size_t p = 0; p < poses.size(); ++p)
        if (poses[p].size() != weights.vertexCount())
            throw std::invalid_argument("motion fit: pose " + std::to_string(p) + " has " +
                                        std::to_string(poses[p].size()) + " vertices, the weights " +
                                        std::to_string(weights.vertexCount()));
}

} // namespace

RigMotionFit fitRigToMotion(const SkeletonRig& rig, const BoneWeights& weights, const std::vector<PosePositions>& poses,
                            std::size_t restPose, const RigMotionFitOptions& options, const TaskControl& control)
{
    requireFittable(rig, weights, poses, restPose);
    const auto start = std::chrono::steady_clock::now();
    const MotionModel model = motionModel(rig, weights, poses[restPose]);
    RigMotionFit fit;
    fit.poses.assign(poses.size(), trimlab::restPose(rig));
    std::size_t done = 0;
    auto fitFrom = [&](std::size_t pose, std::size_t from) {
        control.throwIfCancelled();
        fit.poses[pose] = fit.poses[from];
        fit.iterations += fitPose(rig, model, poses[pose], fit.poses[pose], options);
        control.report("motion fit", ++done, poses.size());
    };
    control.report("motion fit", 0, poses.size());
    fitFrom(restPose, restPose);
    for (std::size_t p = restPose + 1; p < poses.size(); ++p)
        fitFrom(p, p - 1);
    for (std::size_t p = restPose; p-- > 0;)
        fitFrom(p, p + 1);
    std::vector<glm::vec3> rest(poses[restPose].size());
    for (std::size_t v = 0; v < rest.size(); ++v)
        rest[v] = glm::vec3(poses[restPose][v]);
    std::vector<PosePositions> skinned;
    skinned.reserve(poses.size());
    for (const SkeletonPose& pose : fit.poses) {
        const std::vector<glm::vec3> positions = posePositions(rest, rig, weights, pose, SkinningMethod::Lbs);
        skinned.emplace_back(positions.begin(), positions.end());
    }
    fit.error = measureSkinningError(poses, skinned, restPose);
    fit.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return fit;
}

std::string describeRigMotionFit(const RigMotionFit& fit)
{
    char line[160];
    std::snprintf(line, sizeof line, "E_RMS %.4g (E_RMS/diagonal %.4f) over %zu poses, fitted in %.2f s",
                  fit.error.eRms, fit.error.eRmsDiagonal, fit.poses.size(), fit.milliseconds * 1e-3);
    return line;
}

} // namespace trimlab
