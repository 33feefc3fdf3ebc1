#include "core/skinning/skinning_lbs_fit.h"

#include "core/util/parallel_for.h"
#include "core/skinning/skinning_normal_equations.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace detail {

void requireFitSizes(std::size_t source, std::size_t target, std::size_t weights)
{
    if (source != target || source != weights)
        throw std::invalid_argument("skinning fit: " + std::to_string(source) + " source, " + std::to_string(target) +
                                    " target and " + std::to_string(weights) + " weighted vertices");
}

BoneFrames boneFrames(std::span<const glm::dvec3> source, const SkinningWeights& weights)
{
    const std::size_t bones = weights.boneCount;
    BoneFrames frames{std::vector<glm::dvec3>(bones, glm::dvec3(0.0)), std::vector<double>(bones, 0.0)};
    std::vector<double> mass(bones, 0.0);
    glm::dvec3 all(0.0);
    for (std::size_t j = 0; j < source.size(); ++j) {
        all += source[j];
        const VertexInfluences& in = weights.vertices[j];
        for (std::uint32_t i = 0; i < in.count; ++i) {
            frames.centroid[in.bones[i]] += in.weights[i] * source[j];
            mass[in.bones[i]] += in.weights[i];
        }
    }
    all /= double(std::max<std::size_t>(source.size(), 1));
    for (std::size_t b = 0; b < bones; ++b)
        frames.centroid[b] = mass[b] > 0.0 ? frames.centroid[b] / mass[b] : all;
    for (std::size_t j = 0; j < source.size(); ++j) {
        const VertexInfluences& in = weights.vertices[j];
        for (std::uint32_t i = 0; i < in.count; ++i) {
            const glm::dvec3 d = source[j] - frames.centroid[in.bones[i]];
            frames.radius[in.bones[i]] += in.weights[i] * glm::dot(d, d);
        }
    }
    for (std::size_t b = 0; b < bones; ++b) {
        const double r = mass[b] > 0.0 ? std::sqrt(frames.radius[b] / mass[b]) : 0.0;
        frames.radius[b] = r > 0.0 ? r : 1.0;
    }
    return frames;
}

namespace {

// The identity map in the per-bone parameterisation Q(x) = A·(x − c)/σ + a.
Eigen::MatrixXd identityPrior(const BoneFrames& frames)
{
    const Eigen::Index bones = Eigen::Index(frames.centroid.size());
    Eigen::MatrixXd prior = Eigen::MatrixXd::Zero(4 * bones, 3);
    for (Eigen::Index b = 0; b < bones; ++b)
        for (int r = 0; r < 3; ++r) {
            prior(4 * b + r, r) = frames.radius[std::size_t(b)];
            prior(4 * b + 3, r) = frames.centroid[std::size_t(b)][r];
        }
    return prior;
}

void addChunk(BoneBlockSystem& system, std::span<const glm::dvec3> source, std::span<const glm::dvec3> target,
              const SkinningWeights& weights, const BoneFrames& frames, std::size_t begin, std::size_t end)
{
    std::array<double, 4 * kMaxInfluences> row{};
    for (std::size_t j = begin; j < end; ++j) {
        const VertexInfluences& in = weights.vertices[j];
        for (std::uint32_t i = 0; i < in.count; ++i) {
            const std::uint32_t b = in.bones[i];
            const glm::dvec3 local = (source[j] - frames.centroid[b]) / frames.radius[b];
            row[4 * i + 0] = in.weights[i] * local.x;
            row[4 * i + 1] = in.weights[i] * local.y;
            row[4 * i + 2] = in.weights[i] * local.z;
            row[4 * i + 3] = in.weights[i];
        }
        const double rhs[3] = {target[j].x, target[j].y, target[j].z};
        system.addVertex(in, j, 1, row.data(), rhs);
    }
}

} // namespace

std::vector<Affine3> fitAffineBoneTransforms(std::span<const glm::dvec3> source, std::span<const glm::dvec3> target,
                                             const SkinningWeights& weights, const BonePairPattern& pattern,
                                             const PoseFitOptions& options)
{
    requireFitSizes(source.size(), target.size(), weights.vertices.size());
    const BoneFrames frames = boneFrames(source, weights);
    const std::size_t chunks = chunkCount(source.size());
    std::vector<BoneBlockSystem> partial(chunks, BoneBlockSystem(pattern, 4, 3));
    parallelFor(chunks, options.threads, [&](std::size_t c) {
        const auto [begin, end] = chunkRange(source.size(), c);
        addChunk(partial[c], source, target, weights, frames, begin, end);
    });
    for (std::size_t c = 1; c < chunks; ++c)
        partial[0].add(partial[c]);
    const Eigen::MatrixXd x = partial[0].solve(identityPrior(frames), 1e-10, 0.0, options.solver);

    std::vector<Affine3> transforms(weights.boneCount);
    for (std::size_t b = 0; b < weights.boneCount; ++b) {
        Affine3& q = transforms[b];
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c)
                q.linear[c][r] = x(Eigen::Index(4 * b) + c, r) / frames.radius[b]; // glm: [column][row]
            q.translation[r] = x(Eigen::Index(4 * b) + 3, r);
        }
        q.translation -= q.linear * frames.centroid[b];
    }
    return transforms;
}

} // namespace detail

std::vector<Affine3> fitAffineBoneTransforms(std::span<const glm::dvec3> source, std::span<const glm::dvec3> target,
                                             const SkinningWeights& weights, const PoseFitOptions& options)
{
    detail::requireFitSizes(source.size(), target.size(), weights.vertices.size());
    const detail::BonePairPattern pattern = detail::bonePairPattern(weights);
    return detail::fitAffineBoneTransforms(source, target, weights, pattern, options);
}

} // namespace trimlab
