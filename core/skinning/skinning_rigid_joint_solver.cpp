#include "core/skinning/skinning_rigid_joint_solver.h"

#include <Eigen/Dense>

namespace trimlab {

struct RigidJointSolver::NormalMatrix {
    Eigen::LDLT<Eigen::MatrixXd> ldlt;
};

namespace {

Eigen::MatrixXd regularisedGram(const SkinningWeights& weights, double& lambda)
{
    const auto bones = Eigen::Index(weights.boneCount);
    Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(bones, bones);
    for (const VertexInfluences& in : weights.vertices)
        for (std::uint32_t a = 0; a < in.count; ++a)
            for (std::uint32_t b = 0; b < in.count; ++b)
                gram(in.bones[a], in.bones[b]) += in.weights[a] * in.weights[b];
    lambda = 1e-9 * (gram.trace() > 0.0 ? gram.trace() / double(bones) : 1.0);
    gram.diagonal().array() += lambda;
    return gram;
}

double squaredError(const std::vector<glm::dvec3>& skinned, std::span<const glm::dvec3> target)
{
    double e = 0.0;
    for (std::size_t j = 0; j < skinned.size(); ++j) {
        const glm::dvec3 d = skinned[j] - target[j];
        e += glm::dot(d, d);
    }
    return e;
}

} // namespace

glm::dmat3 closestRotation(const glm::dmat3& m)
{
    Eigen::Matrix3d a;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            a(r, c) = m[c][r];
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d u = svd.matrixU();
    if ((u * svd.matrixV().transpose()).determinant() < 0.0)
        u.col(2) *= -1.0; // the smallest singular direction absorbs the reflection
    const Eigen::Matrix3d rotation = u * svd.matrixV().transpose();
    glm::dmat3 result;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            result[c][r] = rotation(r, c);
    return result;
}

RigidJointSolver::RigidJointSolver(const SkinningWeights& weights, std::span<const glm::dvec3> restPositions)
    : m_rest(restPositions), m_boneVertices(weights.boneCount)
{
    for (std::size_t j = 0; j < weights.vertices.size(); ++j) {
        const VertexInfluences& in = weights.vertices[j];
        for (std::uint32_t i = 0; i < in.count; ++i)
            m_boneVertices[in.bones[i]].emplace_back(std::uint32_t(j), in.weights[i]);
    }
    m_gram = std::make_shared<const NormalMatrix>(
        NormalMatrix{Eigen::LDLT<Eigen::MatrixXd>(regularisedGram(weights, m_lambda))});
}

std::vector<glm::dvec3> RigidJointSolver::skinned(const std::vector<RigidJointPose>& joints) const
{
    std::vector<glm::dvec3> result(m_rest.size(), glm::dvec3(0.0));
    for (std::size_t b = 0; b < joints.size(); ++b) {
        const glm::dmat3 r = glm::mat3_cast(joints[b].rotation);
        for (const auto& [j, w] : m_boneVertices[b])
            result[j] += w * (r * m_rest[j] + joints[b].translation);
    }
    return result;
}

void RigidJointSolver::solveTranslations(std::vector<RigidJointPose>& joints, std::span<const glm::dvec3> target,
                                         const std::vector<glm::dvec3>& prior) const
{
    const auto bones = Eigen::Index(joints.size());
    Eigen::MatrixXd rhs(bones, 3);
    for (Eigen::Index b = 0; b < bones; ++b)
        for (int c = 0; c < 3; ++c)
            rhs(b, c) = m_lambda * prior[std::size_t(b)][c];
    for (std::size_t b = 0; b < joints.size(); ++b)
        joints[b].translation = glm::dvec3(0.0);
    const std::vector<glm::dvec3> rotated = skinned(joints); // Σ_b w_bj R_b v_j
    for (std::size_t b = 0; b < joints.size(); ++b)
        for (const auto& [j, w] : m_boneVertices[b])
            for (int c = 0; c < 3; ++c)
                rhs(Eigen::Index(b), c) += w * (target[j][c] - rotated[j][c]);
    const Eigen::MatrixXd t = m_gram->ldlt.solve(rhs);
    for (Eigen::Index b = 0; b < bones; ++b)
        joints[std::size_t(b)].translation = glm::dvec3(t(b, 0), t(b, 1), t(b, 2));
}

void RigidJointSolver::solveBoneMotions(std::vector<RigidJointPose>& joints, std::span<const glm::dvec3> target) const
{
    std::vector<glm::dvec3> current = skinned(joints);
    for (std::size_t b = 0; b < joints.size(); ++b) {
        const auto& vertices = m_boneVertices[b];
        const glm::dmat3 oldRotation = glm::mat3_cast(joints[b].rotation);
        const glm::dvec3 oldTranslation = joints[b].translation;
        // r_j: the target minus every other bone's part; min Σ w²‖R v + t − r/w‖².
        double w2 = 0.0;
        glm::dvec3 restCentre(0.0), targetCentre(0.0);
        std::vector<glm::dvec3> r(vertices.size());
        for (std::size_t k = 0; k < vertices.size(); ++k) {
            const auto [j, w] = vertices[k];
            r[k] = target[j] - current[j] + w * (oldRotation * m_rest[j] + oldTranslation);
            w2 += w * w;
            restCentre += w * w * m_rest[j];
            targetCentre += w * r[k];
        }
        if (!(w2 > 0.0))
            continue;
        restCentre /= w2;
        targetCentre /= w2;
        glm::dmat3 m(0.0);
        for (std::size_t k = 0; k < vertices.size(); ++k) {
            const auto [j, w] = vertices[k];
            m += glm::outerProduct(w * r[k] - w * w * targetCentre, m_rest[j] - restCentre);
        }
        const glm::dmat3 rotation = closestRotation(m);
        const glm::dvec3 translation = targetCentre - rotation * restCentre;
        for (const auto& [j, w] : vertices)
            current[j] += w * ((rotation * m_rest[j] + translation) - (oldRotation * m_rest[j] + oldTranslation));
        joints[b] = {glm::normalize(glm::quat_cast(rotation)), translation};
    }
}

double RigidJointSolver::solve(std::vector<RigidJointPose>& joints, std::span<const glm::dvec3> target,
                               unsigned sweeps) const
{
    std::vector<glm::dvec3> prior;
    for (const RigidJointPose& joint : joints)
        prior.push_back(joint.translation);
    solveTranslations(joints, target, prior);
    double error = squaredError(skinned(joints), target);
    for (unsigned sweep = 0; sweep < sweeps && error > 0.0; ++sweep) {
        std::vector<RigidJointPose> next = joints;
        solveBoneMotions(next, target);
        solveTranslations(next, target, prior);
        const double nextError = squaredError(skinned(next), target);
        if (!(nextError < error))
            break; // λ or rounding: keep the better motions
        joints = std::move(next);
        const bool converged = error - nextError <= 1e-8 * error;
        error = nextError;
        if (converged)
            break;
    }
    return error;
}

} // namespace trimlab
