#include "core/skinning/skinning_decomposition.h"

#include "core/skinning/convex_vertex_weights.h"
#include "core/skinning/skinning_pose_fit.h"
#include "core/skinning/skinning_rigid_joint_solver.h"
#include "core/skinning/skinning_normal_equations.h"
#include "core/util/parallel_for.h"

#include <Eigen/Dense>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

// Σ_t ‖Σ_b w_bj M_b^t v_j − y_j^t‖²: vertex j's error over every pose.
double vertexSquaredError(const std::vector<PosePositions>& poses, const std::vector<glm::dvec3>& rest,
                          const SkinningWeights& weights, const std::vector<std::vector<Affine3>>& matrices,
                          std::size_t j)
{
    const VertexInfluences& in = weights.vertices[j];
    double sum = 0.0;
    for (std::size_t t = 0; t < poses.size(); ++t) {
        glm::dvec3 p(0.0);
        for (std::uint32_t i = 0; i < in.count; ++i)
            p += in.weights[i] * matrices[t][in.bones[i]].apply(rest[j]);
        const glm::dvec3 d = p - poses[t][j];
        sum += glm::dot(d, d);
    }
    return sum;
}

// The rigid matrix as the solver's rotation and translation, and back.
RigidJointPose toJoint(const Affine3& m)
{
    return {glm::normalize(glm::quat_cast(m.linear)), m.translation};
}

Affine3 toMatrix(const RigidJointPose& joint)
{
    return {glm::mat3_cast(joint.rotation), joint.translation};
}

std::vector<RigidJointPose> toJoints(const std::vector<Affine3>& matrices)
{
    std::vector<RigidJointPose> joints;
    joints.reserve(matrices.size());
    for (const Affine3& m : matrices)
        joints.push_back(toJoint(m));
    return joints;
}

// Σ over poses and vertices of the squared distance, summed per chunk in chunk order.
double squaredError(const std::vector<PosePositions>& poses, const std::vector<glm::dvec3>& rest,
                    const SkinningWeights& weights, const std::vector<std::vector<Affine3>>& matrices, unsigned threads,
                    const TaskControl& control)
{
    const std::size_t chunks = detail::chunkCount(rest.size());
    std::vector<double> partial(chunks, 0.0);
    parallelFor(
        chunks, threads,
        [&](std::size_t c) {
            const auto [begin, end] = detail::chunkRange(rest.size(), c);
            double sum = 0.0;
            for (std::size_t j = begin; j < end; ++j)
                sum += vertexSquaredError(poses, rest, weights, matrices, j);
            partial[c] = sum;
        },
        control, "fit");
    double total = 0.0;
    for (double p : partial)
        total += p;
    return total;
}

// Block 1, rigid: every pose but the rest pose, independently, warm-started from `transforms`.
void updateRigidTransforms(std::vector<std::vector<Affine3>>& transforms, const std::vector<PosePositions>& poses,
                           std::size_t restPose, const std::vector<glm::dvec3>& rest, const SkinningWeights& weights,
                           unsigned sweeps, unsigned threads, const TaskControl& control)
{
    const RigidJointSolver solver(weights, rest);
    parallelFor(
        poses.size(), threads,
        [&](std::size_t t) {
            if (t == restPose)
                return;
            std::vector<RigidJointPose> joints = toJoints(transforms[t]);
            (void)solver.solve(joints, poses[t], sweeps);
            for (std::size_t b = 0; b < joints.size(); ++b)
                transforms[t][b] = toMatrix(joints[b]);
        },
        control, "fit");
}

// Procrustes descent has local minima: a pose whose joints settled in a poor one often
// does better started from its neighbour's joints (poses are close in time). In chain order
// (so each pose can pass its improvement on), pose t is solved again from pose t∓1's joints
// and keeps whichever start ends lower — as the glTF export does (skinning_gltf_joints.h).
void improveFromNeighbourPoses(std::vector<std::vector<Affine3>>& transforms, const std::vector<PosePositions>& poses,
                               std::size_t restPose, const std::vector<glm::dvec3>& rest,
                               const SkinningWeights& weights, unsigned sweeps, const TaskControl& control)
{
    const RigidJointSolver solver(weights, rest);
    for (std::size_t t : chainOrder(poses.size(), restPose)) {
        if (t == restPose)
            continue;
        control.throwIfCancelled();
        std::vector<RigidJointPose> own = toJoints(transforms[t]);
        const double ownError = solver.solve(own, poses[t], 0);
        std::vector<RigidJointPose> neighbour = toJoints(transforms[t > restPose ? t - 1 : t + 1]);
        const std::vector<RigidJointPose>& best =
            solver.solve(neighbour, poses[t], sweeps) < ownError ? neighbour : own;
        for (std::size_t b = 0; b < best.size(); ++b)
            transforms[t][b] = toMatrix(best[b]);
    }
}

// Once the weights and rest positions are final, the rest positions are a bind pose fitted
// for all poses, no longer the rest pose itself: the rest pose gets joints of its own (the
// gauge they fixed during the descent is no longer needed), as every other pose.
void fitRestPoseJoints(std::vector<Affine3>& transforms, const PosePositions& restTarget,
                       const std::vector<glm::dvec3>& rest, const SkinningWeights& weights, unsigned sweeps)
{
    double identityError = 0.0;
    for (std::size_t j = 0; j < rest.size(); ++j)
        identityError += glm::dot(rest[j] - restTarget[j], rest[j] - restTarget[j]);
    std::vector<RigidJointPose> joints(transforms.size());
    if (RigidJointSolver(weights, rest).solve(joints, restTarget, sweeps) < identityError)
        for (std::size_t b = 0; b < joints.size(); ++b)
            transforms[b] = toMatrix(joints[b]);
}

// Block 1, affine: the classical rest-to-pose LBS fit of every pose.
void updateAffineTransforms(std::vector<std::vector<Affine3>>& transforms, const std::vector<PosePositions>& poses,
                            std::size_t restPose, const std::vector<glm::dvec3>& rest, const SkinningWeights& weights,
                            unsigned threads, const TaskControl& control)
{
    SkinningModel model = identitySkinningModel(SkinningMethod::Lbs, SkinningChain::RestToPose, poses.size(), restPose,
                                                rest, weights, {});
    PoseFitOptions fit;
    fit.threads = threads;
    fitSkinningTransforms(model, poses, fit, control);
    transforms = std::move(model.affine);
}

std::vector<std::uint32_t> candidateBones(const SkinningWeights& weights, const VertexGraph& graph, std::size_t j)
{
    std::vector<std::uint32_t> bones;
    const auto addOf = [&](std::size_t v) {
        const VertexInfluences& in = weights.vertices[v];
        bones.insert(bones.end(), in.bones.begin(), in.bones.begin() + in.count);
    };
    addOf(j);
    if (j < graph.vertexCount())
        for (std::uint32_t n : graph.neighborsOf(j))
            addOf(n);
    std::sort(bones.begin(), bones.end());
    bones.erase(std::unique(bones.begin(), bones.end()), bones.end());
    return bones;
}

// Gram matrix of the columns M_b^t v_j − y_j^t, stacked over every pose.
Eigen::MatrixXd predictionGram(const std::vector<PosePositions>& poses,
                               const std::vector<std::vector<Affine3>>& matrices, const glm::dvec3& v, std::size_t j,
                               const std::vector<std::uint32_t>& bones)
{
    const auto m = Eigen::Index(bones.size());
    Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(m, m);
    Eigen::MatrixXd columns(3, m);
    for (std::size_t t = 0; t < poses.size(); ++t) {
        for (Eigen::Index c = 0; c < m; ++c) {
            const glm::dvec3 d = matrices[t][bones[std::size_t(c)]].apply(v) - poses[t][j];
            columns.col(c) = Eigen::Vector3d(d.x, d.y, d.z);
        }
        gram.noalias() += columns.transpose() * columns;
    }
    return gram;
}

// Calls perVertex(j) for every vertex, in chunks on `threads` threads; each call writes only
// vertex j's result, so nothing depends on the thread count.
template <class PerVertex>
void forEachVertex(std::size_t vertices, unsigned threads, const TaskControl& control, PerVertex&& perVertex)
{
    parallelFor(
        detail::chunkCount(vertices), threads,
        [&](std::size_t c) {
            const auto [begin, end] = detail::chunkRange(vertices, c);
            for (std::size_t j = begin; j < end; ++j)
                perVertex(j);
        },
        control, "fit");
}

// Block 2.
void updateWeights(SkinningWeights& weights, const std::vector<PosePositions>& poses,
                   const std::vector<glm::dvec3>& rest, const std::vector<std::vector<Affine3>>& matrices,
                   const VertexGraph& graph, std::size_t limit, unsigned threads, const TaskControl& control)
{
    const SkinningWeights old = weights;
    forEachVertex(rest.size(), threads, control, [&](std::size_t j) {
        const std::vector<std::uint32_t> bones = candidateBones(old, graph, j);
        weights.vertices[j] =
            bestConvexInfluences(predictionGram(poses, matrices, rest[j], j, bones), bones, old.vertices[j], limit);
    });
}

// Block 3: v_j = argmin Σ_t ‖N_t v + c_t − y_t‖² with N_t = Σ w_b R_b^t, c_t = Σ w_b t_b^t.
void updateRestPositions(std::vector<glm::dvec3>& rest, const std::vector<PosePositions>& poses,
                         const SkinningWeights& weights, const std::vector<std::vector<Affine3>>& matrices,
                         unsigned threads, const TaskControl& control)
{
    forEachVertex(rest.size(), threads, control, [&](std::size_t j) {
        const VertexInfluences& in = weights.vertices[j];
        glm::dmat3 normal(0.0);
        glm::dvec3 rhs(0.0);
        for (std::size_t t = 0; t < poses.size(); ++t) {
            Affine3 blend{glm::dmat3(0.0), glm::dvec3(0.0)};
            for (std::uint32_t i = 0; i < in.count; ++i)
                blend = weightedSum(blend, matrices[t][in.bones[i]], in.weights[i]);
            normal += glm::transpose(blend.linear) * blend.linear;
            rhs += glm::transpose(blend.linear) * (poses[t][j] - blend.translation);
        }
        // The rest pose's identity term makes `normal` ≥ I: always invertible.
        rest[j] = glm::inverse(normal) * rhs;
    });
}

// Per-vertex Σ_t ‖prediction − target‖².
std::vector<double> vertexErrors(const std::vector<PosePositions>& poses, const std::vector<glm::dvec3>& rest,
                                 const SkinningWeights& weights, const std::vector<std::vector<Affine3>>& matrices)
{
    std::vector<double> errors(rest.size());
    for (std::size_t j = 0; j < rest.size(); ++j)
        errors[j] = vertexSquaredError(poses, rest, weights, matrices, j);
    return errors;
}

// The `size` vertices nearest to `seed` in breadth-first order (graph rings).
std::vector<std::uint32_t> graphBall(const VertexGraph& graph, std::uint32_t seed, std::size_t size)
{
    std::vector<std::uint32_t> ball{seed};
    std::vector<char> seen(graph.vertexCount(), 0);
    seen[seed] = 1;
    for (std::size_t head = 0; head < ball.size() && ball.size() < size; ++head)
        for (std::uint32_t n : graph.neighborsOf(ball[head]))
            if (!seen[n] && ball.size() < size) {
                seen[n] = 1;
                ball.push_back(n);
            }
    return ball;
}

// Bones whose support Σ_j w_bj is below `minSupport` hold few vertices and lower the error
// little; each is moved to where the error is largest: it takes a ball of vertices around
// the worst vertex not yet taken (weight 1, joints from the identity: the next joint block
// fits them to the ball's motion), and the vertices it leaves are handed to their other
// bones (or, with none, to the bone of a neighbour), so the weights stay convex.
std::size_t reseedWeakBones(SkinningDecomposition& d, const std::vector<PosePositions>& poses, const VertexGraph& graph,
                            double minSupport, std::size_t ballSize)
{
    const std::size_t bones = d.weights.boneCount;
    std::vector<double> support(bones, 0.0);
    for (const VertexInfluences& in : d.weights.vertices)
        for (std::uint32_t i = 0; i < in.count; ++i)
            support[in.bones[i]] += in.weights[i];
    std::vector<std::uint32_t> weak;
    for (std::uint32_t b = 0; b < bones; ++b)
        if (support[b] < minSupport)
            weak.push_back(b);
    if (weak.empty() || weak.size() == bones)
        return 0;
    std::vector<char> isWeak(bones, 0);
    for (std::uint32_t b : weak)
        isWeak[b] = 1;
    // Drop the weak bones from every vertex; a vertex left without a bone takes a neighbour's.
    std::vector<std::uint32_t> orphans;
    for (std::size_t j = 0; j < d.weights.vertices.size(); ++j) {
        std::vector<std::pair<std::uint32_t, double>> kept;
        const VertexInfluences& in = d.weights.vertices[j];
        for (std::uint32_t i = 0; i < in.count; ++i)
            if (!isWeak[in.bones[i]])
                kept.emplace_back(in.bones[i], in.weights[i]);
        if (kept.empty()) {
            orphans.push_back(std::uint32_t(j));
        } else {
            const std::uint32_t fallback = kept.front().first;
            d.weights.vertices[j] = sparseInfluences(std::move(kept), fallback, kMaxInfluences);
        }
    }
    std::vector<char> orphan(d.weights.vertices.size(), 0);
    for (std::uint32_t j : orphans)
        orphan[j] = 1;
    for (bool changed = true; changed;) { // flood the remaining bones into orphaned regions
        changed = false;
        for (std::uint32_t j : orphans)
            if (orphan[j])
                for (std::uint32_t n : graph.neighborsOf(j))
                    if (!orphan[n]) {
                        d.weights.vertices[j] = {{d.weights.vertices[n].bones[0]}, {1.0}, 1};
                        orphan[j] = 0;
                        changed = true;
                        break;
                    }
    }
    for (std::uint32_t j : orphans) // a mesh component held only by weak bones: keep the first
        if (orphan[j])
            d.weights.vertices[j] = {{weak.front()}, {1.0}, 1};
    // Seed each weak bone at the worst vertex outside the balls already taken.
    const std::vector<double> errors = vertexErrors(poses, d.restPositions, d.weights, d.transforms);
    std::vector<std::uint32_t> order(errors.size());
    for (std::uint32_t j = 0; j < order.size(); ++j)
        order[j] = j;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return errors[a] > errors[b]; });
    std::vector<char> taken(errors.size(), 0);
    std::size_t next = 0;
    for (std::uint32_t b : weak) {
        while (next < order.size() && taken[order[next]])
            ++next;
        if (next == order.size())
            break;
        for (std::uint32_t j : graphBall(graph, order[next], ballSize)) {
            d.weights.vertices[j] = {{b}, {1.0}, 1};
            taken[j] = 1;
        }
        for (auto& pose : d.transforms)
            pose[b] = Affine3{};
    }
    return weak.size();
}

void requireShapes(const std::vector<PosePositions>& poses, std::size_t restPose, const std::vector<glm::dvec3>& rest,
                   const SkinningWeights& weights)
{
    if (poses.empty())
        throw std::invalid_argument("skinning decomposition: the animation has no poses");
    if (restPose >= poses.size())
        throw std::invalid_argument("skinning decomposition: the rest pose " + std::to_string(restPose) +
                                    " is not one of the " + std::to_string(poses.size()) + " poses");
    if (weights.vertices.size() != rest.size())
        throw std::invalid_argument("skinning decomposition: " + std::to_string(weights.vertices.size()) +
                                    " weights for " + std::to_string(rest.size()) + " vertices");
    for (std::size_t t = 0; t < poses.size(); ++t)
        if (poses[t].size() != rest.size())
            throw std::invalid_argument("skinning decomposition: pose " + std::to_string(t) + " has " +
                                        std::to_string(poses[t].size()) + " vertices, the rest pose " +
                                        std::to_string(rest.size()));
    requireConvexWeights(weights);
}

double eRmsOf(double squared, std::size_t vertices, std::size_t poses)
{
    return 1000.0 * std::sqrt(squared / (3.0 * double(vertices) * double(poses)));
}

} // namespace

SkinningDecomposition decomposeSkinning(const std::vector<PosePositions>& poses, std::size_t restPose,
                                        std::vector<glm::dvec3> restPositions, SkinningWeights weights,
                                        const VertexGraph& graph, const SkinningDecompositionOptions& options,
                                        const TaskControl& control)
{
    requireShapes(poses, restPose, restPositions, weights);
    SkinningDecomposition d;
    d.restPositions = std::move(restPositions);
    d.weights = std::move(weights);
    d.transforms.assign(poses.size(), std::vector<Affine3>(d.weights.boneCount));
    const std::size_t n = d.restPositions.size();
    const double perBone = double(n) / double(d.weights.boneCount);
    // Inner loops report nothing of their own: the stage's items are whole iterations.
    const TaskControl inner{{}, control.stop};
    const unsigned iterations = std::max(1u, options.maxIterations);
    control.report("fit", 0, iterations);
    double previous = 0.0;
    for (unsigned iteration = 0; iteration < iterations; ++iteration) {
        if (options.rigidJoints)
            updateRigidTransforms(d.transforms, poses, restPose, d.restPositions, d.weights,
                                  iteration == 0 ? options.firstJointSweeps : options.jointSweeps, options.threads,
                                  inner);
        else
            updateAffineTransforms(d.transforms, poses, restPose, d.restPositions, d.weights, options.threads, inner);
        if (iteration == 0)
            d.firstFitERms = eRmsOf(
                squaredError(poses, d.restPositions, d.weights, d.transforms, options.threads, inner), n, poses.size());
        if (options.updateWeights)
            updateWeights(d.weights, poses, d.restPositions, d.transforms, graph, options.maxInfluences,
                          options.threads, inner);
        if (options.updateRestPositions)
            updateRestPositions(d.restPositions, poses, d.weights, d.transforms, options.threads, inner);
        const std::size_t moved = iteration < options.reseedIterations && options.updateWeights
                                      ? reseedWeakBones(d, poses, graph, options.minBoneSupport * perBone,
                                                        std::max<std::size_t>(1, std::size_t(perBone)))
                                      : 0;
        d.reseededBones += moved;
        const bool reseeded = moved > 0;
        const double e = squaredError(poses, d.restPositions, d.weights, d.transforms, options.threads, inner);
        d.eRmsHistory.push_back(eRmsOf(e, n, poses.size()));
        d.iterations = iteration + 1;
        control.report("fit", iteration + 1, iterations);
        if (reseeded) {
            previous = 0.0; // the descent starts again from the moved bones
            continue;
        }
        if (previous > 0.0 && !(previous - e > options.minRelativeGain * previous))
            break;
        previous = e;
    }
    // The last weight and rest updates moved the optimum of the transforms: one more
    // transform block (more sweeps for rigid joints), which can only lower E.
    if (options.updateWeights || options.updateRestPositions) {
        if (options.rigidJoints) {
            updateRigidTransforms(d.transforms, poses, restPose, d.restPositions, d.weights, options.finalJointSweeps,
                                  options.threads, inner);
            improveFromNeighbourPoses(d.transforms, poses, restPose, d.restPositions, d.weights,
                                      options.finalJointSweeps, inner);
            fitRestPoseJoints(d.transforms[restPose], poses[restPose], d.restPositions, d.weights,
                              options.finalJointSweeps);
        } else
            updateAffineTransforms(d.transforms, poses, restPose, d.restPositions, d.weights, options.threads, inner);
        d.eRmsHistory.push_back(eRmsOf(
            squaredError(poses, d.restPositions, d.weights, d.transforms, options.threads, inner), n, poses.size()));
    }
    control.report("fit", iterations, iterations);
    return d;
}

SkinningModel decomposedSkinningModel(const SkinningDecomposition& decomposition, std::size_t restPose,
                                      std::vector<glm::uvec3> triangles)
{
    SkinningModel model =
        identitySkinningModel(SkinningMethod::Lbs, SkinningChain::RestToPose, decomposition.transforms.size(), restPose,
                              decomposition.restPositions, decomposition.weights, std::move(triangles));
    model.affine = decomposition.transforms;
    return model;
}

} // namespace trimlab
