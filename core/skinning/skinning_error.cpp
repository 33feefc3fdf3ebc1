#include "core/skinning/skinning_error.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

double boundingDiagonal(const PosePositions& positions)
{
    if (positions.empty())
        return 0.0;
    glm::dvec3 lo = positions.front(), hi = positions.front();
    for (const glm::dvec3& p : positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return glm::length(hi - lo);
}

void requireSameShape(const std::vector<PosePositions>& a, const std::vector<PosePositions>& b)
{
    if (a.empty() || a.size() != b.size())
        throw std::invalid_argument("skinning error: " + std::to_string(a.size()) + " original and " +
                                    std::to_string(b.size()) + " approximated poses");
    for (std::size_t t = 0; t < a.size(); ++t)
        if (a[t].size() != a.front().size() || b[t].size() != a.front().size())
            throw std::invalid_argument("skinning error: pose " + std::to_string(t) + " has a different vertex count");
}

} // namespace

SkinningError measureSkinningError(const std::vector<PosePositions>& original,
                                   const std::vector<PosePositions>& approximation, std::size_t restPose)
{
    requireSameShape(original, approximation);
    const std::size_t poses = original.size();
    const std::size_t vertices = original.front().size();
    SkinningError error;
    error.perPose.assign(poses, 0.0);
    error.perVertex.assign(vertices, 0.0);
    double total = 0.0;
    for (std::size_t t = 0; t < poses; ++t) {
        double pose = 0.0;
        for (std::size_t j = 0; j < vertices; ++j) {
            const glm::dvec3 d = original[t][j] - approximation[t][j];
            const double squared = glm::dot(d, d);
            pose += squared;
            error.perVertex[j] += squared;
            error.maxDistance = std::max(error.maxDistance, std::sqrt(squared));
        }
        error.perPose[t] = vertices > 0 ? 1000.0 * std::sqrt(pose / (3.0 * double(vertices))) : 0.0;
        total += pose;
    }
    for (double& v : error.perVertex)
        v = std::sqrt(v / double(poses));
    const double count = double(poses) * double(vertices);
    error.frobenius = std::sqrt(total);
    error.rmse = count > 0.0 ? std::sqrt(total / count) : 0.0;
    error.eRms = count > 0.0 ? 1000.0 * std::sqrt(total / (3.0 * count)) : 0.0;
    error.diagonal = boundingDiagonal(original[std::min(restPose, poses - 1)]);
    error.eRmsDiagonal = error.diagonal > 0.0 ? error.eRms / error.diagonal : 0.0;
    return error;
}

std::vector<double> poseVertexErrors(const PosePositions& original, const PosePositions& approximation)
{
    if (original.size() != approximation.size())
        throw std::invalid_argument("poseVertexErrors: the pose has " + std::to_string(original.size()) +
                                    " vertices, its approximation " + std::to_string(approximation.size()));
    std::vector<double> errors(original.size());
    for (std::size_t j = 0; j < original.size(); ++j)
        errors[j] = glm::length(original[j] - approximation[j]);
    return errors;
}

std::vector<PosePositions> animationPositions(const MeshAnimation& animation)
{
    std::vector<PosePositions> poses;
    poses.reserve(animation.poseCount());
    for (const auto& pose : animation.poses)
        poses.push_back(toDoublePositions(pose));
    return poses;
}

} // namespace trimlab
