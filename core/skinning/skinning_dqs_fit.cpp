#include "core/skinning/skinning_dqs_fit.h"

#include "core/util/parallel_for.h"
#include "core/skinning/skinning_lbs_fit.h"
#include "core/skinning/skinning_normal_equations.h"

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

using Dq8 = std::array<double, 8>; // (real w x y z, dual w x y z)

Dq8 toArray(const DualQuaternion& q)
{
    return {q.real.w, q.real.x, q.real.y, q.real.z, q.dual.w, q.dual.x, q.dual.y, q.dual.z};
}

DualQuaternion fromArray(const Dq8& a)
{
    return {glm::dquat(a[0], a[1], a[2], a[3]), glm::dquat(a[4], a[5], a[6], a[7])};
}

glm::dquat rotationFromVector(const glm::dvec3& omega)
{
    const double angle = glm::length(omega);
    if (angle < 1e-12)
        return glm::normalize(glm::dquat(1.0, 0.5 * omega.x, 0.5 * omega.y, 0.5 * omega.z));
    const glm::dvec3 axis = omega / angle;
    const double s = std::sin(0.5 * angle);
    return glm::dquat(std::cos(0.5 * angle), s * axis.x, s * axis.y, s * axis.z);
}

// The LM update of one bone: rotate by ω about `pivot` (the image of the bone's centroid),
// then translate by τ, after the current transform q.
DualQuaternion perturbed(const DualQuaternion& q, const std::array<double, 6>& delta, const glm::dvec3& pivot)
{
    const glm::dvec3 omega(delta[0], delta[1], delta[2]);
    const glm::dvec3 tau(delta[3], delta[4], delta[5]);
    const glm::dquat r = rotationFromVector(omega);
    return dualQuaternionFromRigid(r, pivot + tau - r * pivot) * q;
}

// d(perturbed)/dδ at δ = 0: 8×6, row-major, by central differences.
std::array<double, 48> parameterJacobian(const DualQuaternion& q, const glm::dvec3& pivot, double radius)
{
    std::array<double, 48> jacobian{};
    for (int k = 0; k < 6; ++k) {
        const double h = k < 3 ? 1e-6 : 1e-6 * radius;
        std::array<double, 6> plus{}, minus{};
        plus[std::size_t(k)] = h;
        minus[std::size_t(k)] = -h;
        const Dq8 a = toArray(perturbed(q, plus, pivot));
        const Dq8 b = toArray(perturbed(q, minus, pivot));
        for (int c = 0; c < 8; ++c)
            jacobian[std::size_t(c * 6 + k)] = (a[std::size_t(c)] - b[std::size_t(c)]) / (2.0 * h);
    }
    return jacobian;
}

glm::dvec3 blendedPoint(const Dq8& blend, const glm::dvec3& s)
{
    return transformPoint(normalized(fromArray(blend)), s);
}

glm::dvec3 vectorPart(const glm::dquat& q)
{
    return {q.x, q.y, q.z};
}

// d position / d blend component, analytically. For the unnormalised blend b = (r, d) the
// blended point is p = vec(r ŝ r* + 2 d r*) / |r|² (ŝ = (0, s); the part of d along r
// that normalized() removes contributes vec(r r*) = 0), so with basis quaternions e_k:
// ∂p/∂r_k = (2 vec(e_k ŝ r*) + 2 vec(d e_k*)) / |r|² − 2 r_k p / |r|²,
// ∂p/∂d_k = 2 vec(e_k r*) / |r|².
void positionJacobian(const Dq8& b, const glm::dvec3& s, double out[3][8])
{
    const glm::dquat r(b[0], b[1], b[2], b[3]), d(b[4], b[5], b[6], b[7]);
    const double n2 = glm::dot(r, r);
    const glm::dquat rc = glm::conjugate(r);
    const glm::dquat shrc = glm::dquat(0.0, s.x, s.y, s.z) * rc;
    const glm::dvec3 p = (vectorPart(r * shrc) + 2.0 * vectorPart(d * rc)) / n2;
    const double rk[4] = {r.w, r.x, r.y, r.z};
    for (int k = 0; k < 4; ++k) {
        glm::dquat e(0.0, 0.0, 0.0, 0.0);
        (k == 0 ? e.w : k == 1 ? e.x : k == 2 ? e.y : e.z) = 1.0;
        const glm::dvec3 dr =
            (2.0 * vectorPart(e * shrc) + 2.0 * vectorPart(d * glm::conjugate(e))) / n2 - 2.0 * rk[k] * p / n2;
        const glm::dvec3 dd = 2.0 * vectorPart(e * rc) / n2;
        for (int row = 0; row < 3; ++row) {
            out[row][k] = dr[row];
            out[row][4 + k] = dd[row];
        }
    }
}

// The unnormalised blend Σ w_i ±q̂_i of vertex j, signs aligned with the first influence.
Dq8 vertexBlend(const VertexInfluences& in, const std::vector<DualQuaternion>& q, std::array<double, 4>& signs)
{
    Dq8 sum{};
    const DualQuaternion& pivot = q[in.bones[0]];
    for (std::uint32_t i = 0; i < in.count; ++i) {
        const DualQuaternion& qi = q[in.bones[i]];
        signs[i] = glm::dot(qi.real, pivot.real) < 0.0 ? -1.0 : 1.0;
        const Dq8 a = toArray(qi);
        for (std::size_t c = 0; c < 8; ++c)
            sum[c] += signs[i] * in.weights[i] * a[c];
    }
    return sum;
}

double chunkCost(std::span<const glm::dvec3> source, std::span<const glm::dvec3> target, const SkinningWeights& weights,
                 const std::vector<DualQuaternion>& q, std::size_t begin, std::size_t end)
{
    double cost = 0.0;
    std::array<double, 4> signs{};
    for (std::size_t j = begin; j < end; ++j) {
        const glm::dvec3 r = target[j] - blendedPoint(vertexBlend(weights.vertices[j], q, signs), source[j]);
        cost += glm::dot(r, r);
    }
    return cost;
}

double totalCost(std::span<const glm::dvec3> source, std::span<const glm::dvec3> target, const SkinningWeights& weights,
                 const std::vector<DualQuaternion>& q, unsigned threads)
{
    const std::size_t chunks = detail::chunkCount(source.size());
    std::vector<double> partial(chunks, 0.0);
    parallelFor(chunks, threads, [&](std::size_t c) {
        const auto [begin, end] = detail::chunkRange(source.size(), c);
        partial[c] = chunkCost(source, target, weights, q, begin, end);
    });
    double cost = 0.0;
    for (double p : partial)
        cost += p;
    return cost;
}

// Adds the Gauss–Newton terms JᵀJ and Jᵀr of one vertex.
void addVertexTerms(detail::BoneBlockSystem& system, std::size_t j, const glm::dvec3& s, const glm::dvec3& d,
                    const VertexInfluences& in, const std::vector<DualQuaternion>& q,
                    const std::vector<std::array<double, 48>>& dq)
{
    std::array<double, 4> signs{};
    const Dq8 blend = vertexBlend(in, q, signs);
    const glm::dvec3 r = d - blendedPoint(blend, s);
    double dpdb[3][8];
    positionJacobian(blend, s, dpdb);
    std::array<double, 3 * 6 * kMaxInfluences> jacobian{};
    const int width = int(in.count) * 6;
    for (std::uint32_t i = 0; i < in.count; ++i) {
        const std::array<double, 48>& dqi = dq[in.bones[i]];
        const double factor = signs[i] * in.weights[i];
        for (int row = 0; row < 3; ++row)
            for (int k = 0; k < 6; ++k) {
                double sum = 0.0;
                for (int c = 0; c < 8; ++c)
                    sum += dpdb[row][c] * dqi[std::size_t(c * 6 + k)];
                jacobian[std::size_t(row * width + int(i) * 6 + k)] = factor * sum;
            }
    }
    const double residual[3] = {r.x, r.y, r.z};
    system.addVertex(in, j, 3, jacobian.data(), residual);
}

std::vector<DualQuaternion> kabschInitialisation(std::span<const glm::dvec3> source, std::span<const glm::dvec3> target,
                                                 const SkinningWeights& weights)
{
    std::vector<DualQuaternion> result(weights.boneCount);
    std::vector<std::vector<std::size_t>> members(weights.boneCount);
    std::vector<std::vector<double>> omega(weights.boneCount);
    for (std::size_t j = 0; j < source.size(); ++j) {
        const VertexInfluences& in = weights.vertices[j];
        for (std::uint32_t i = 0; i < in.count; ++i) {
            members[in.bones[i]].push_back(j);
            omega[in.bones[i]].push_back(in.weights[i] * in.weights[i]);
        }
    }
    std::vector<glm::dvec3> s, d;
    for (std::size_t b = 0; b < weights.boneCount; ++b) {
        s.clear();
        d.clear();
        for (std::size_t j : members[b]) {
            s.push_back(source[j]);
            d.push_back(target[j]);
        }
        result[b] = fitRigidMotion(s, d, omega[b]);
    }
    return result;
}

} // namespace

DualQuaternion fitRigidMotion(std::span<const glm::dvec3> source, std::span<const glm::dvec3> target,
                              std::span<const double> omega)
{
    double mass = 0.0;
    glm::dvec3 sc(0.0), dc(0.0);
    for (std::size_t i = 0; i < source.size(); ++i) {
        mass += omega[i];
        sc += omega[i] * source[i];
        dc += omega[i] * target[i];
    }
    if (!(mass > 0.0))
        return {};
    sc /= mass;
    dc /= mass;
    Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
    for (std::size_t i = 0; i < source.size(); ++i) {
        const glm::dvec3 a = source[i] - sc, b = target[i] - dc;
        h += omega[i] * Eigen::Vector3d(a.x, a.y, a.z) * Eigen::Vector3d(b.x, b.y, b.z).transpose();
    }
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d correction = Eigen::Matrix3d::Identity();
    correction(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
    const Eigen::Matrix3d r = svd.matrixV() * correction * svd.matrixU().transpose();
    glm::dmat3 rotation;
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col)
            rotation[col][row] = r(row, col);
    const glm::dquat q = glm::normalize(glm::quat_cast(rotation));
    return dualQuaternionFromRigid(q, dc - q * sc);
}

namespace detail {

namespace {

// JᵀJ and Jᵀr of the whole pose at the transforms q; `pivots` receives each bone's
// rotation centre (the image of its centroid) that the parameters refer to.
BoneBlockSystem gaussNewtonSystem(std::span<const glm::dvec3> source, std::span<const glm::dvec3> target,
                                  const SkinningWeights& weights, const BonePairPattern& pattern,
                                  const BoneFrames& frames, const std::vector<DualQuaternion>& q,
                                  const PoseFitOptions& options, std::vector<glm::dvec3>& pivots)
{
    std::vector<std::array<double, 48>> dq(q.size());
    for (std::size_t b = 0; b < q.size(); ++b) {
        pivots[b] = transformPoint(q[b], frames.centroid[b]);
        dq[b] = parameterJacobian(q[b], pivots[b], frames.radius[b]);
    }
    const std::size_t chunks = chunkCount(source.size());
    std::vector<BoneBlockSystem> partial(chunks, BoneBlockSystem(pattern, 6, 1));
    parallelFor(chunks, options.threads, [&](std::size_t c) {
        const auto [begin, end] = chunkRange(source.size(), c);
        for (std::size_t j = begin; j < end; ++j)
            addVertexTerms(partial[c], j, source[j], target[j], weights.vertices[j], q, dq);
    });
    for (std::size_t c = 1; c < chunks; ++c)
        partial[0].add(partial[c]);
    return std::move(partial[0]);
}

} // namespace

std::vector<DualQuaternion> fitRigidBoneTransforms(std::span<const glm::dvec3> source,
                                                   std::span<const glm::dvec3> target, const SkinningWeights& weights,
                                                   const BonePairPattern& pattern,
                                                   std::span<const DualQuaternion> initial,
                                                   const PoseFitOptions& options)
{
    requireFitSizes(source.size(), target.size(), weights.vertices.size());
    if (!initial.empty() && initial.size() != weights.boneCount)
        throw std::invalid_argument("rigid skinning fit: " + std::to_string(initial.size()) +
                                    " initial transforms for " + std::to_string(weights.boneCount) + " bones");
    std::vector<DualQuaternion> q = initial.empty() ? kabschInitialisation(source, target, weights)
                                                    : std::vector<DualQuaternion>(initial.begin(), initial.end());
    const BoneFrames frames = boneFrames(source, weights);
    const std::size_t bones = weights.boneCount;
    double cost = totalCost(source, target, weights, q, options.threads);
    double mu = 1e-6;
    for (unsigned iteration = 0; iteration < options.rigidIterations && cost > 0.0; ++iteration) {
        std::vector<glm::dvec3> pivots(bones);
        const BoneBlockSystem system = gaussNewtonSystem(source, target, weights, pattern, frames, q, options, pivots);
        const Eigen::MatrixXd prior = Eigen::MatrixXd::Zero(Eigen::Index(bones) * 6, 1);
        bool improved = false;
        while (!improved && mu < 1e10) {
            const Eigen::MatrixXd delta = system.solve(prior, 1e-12, mu, options.solver);
            std::vector<DualQuaternion> candidate(bones);
            for (std::size_t b = 0; b < bones; ++b) {
                std::array<double, 6> step{};
                for (std::size_t k = 0; k < 6; ++k)
                    step[k] = delta(Eigen::Index(6 * b + k), 0);
                candidate[b] = normalized(perturbed(q[b], step, pivots[b]));
            }
            const double candidateCost = totalCost(source, target, weights, candidate, options.threads);
            if (candidateCost < cost) {
                improved = true;
                const double decrease = cost - candidateCost;
                q = std::move(candidate);
                cost = candidateCost;
                mu = std::max(mu / 10.0, 1e-12);
                if (decrease <= 1e-6 * (cost + decrease))
                    return q;
            } else {
                mu *= 10.0;
            }
        }
        if (!improved)
            break;
    }
    return q;
}

} // namespace detail

std::vector<DualQuaternion> fitRigidBoneTransforms(std::span<const glm::dvec3> source,
                                                   std::span<const glm::dvec3> target, const SkinningWeights& weights,
                                                   std::span<const DualQuaternion> initial,
                                                   const PoseFitOptions& options)
{
    detail::requireFitSizes(source.size(), target.size(), weights.vertices.size());
    const detail::BonePairPattern pattern = detail::bonePairPattern(weights);
    return detail::fitRigidBoneTransforms(source, target, weights, pattern, initial, options);
}

} // namespace trimlab
