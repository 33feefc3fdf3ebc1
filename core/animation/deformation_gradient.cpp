#include "core/animation/deformation_gradient.h"

#include <Eigen/Dense>
#include <Eigen/SVD>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace trimlab {

namespace {

// Relative size below which a triangle's frame is treated as singular (see the header).
constexpr double kDegenerateRatio = 1e-10;

bool isFinite(const TriangleCorners& c)
{
    for (const glm::dvec3& p : c) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return false;
    }
    return true;
}

// [v2−v1, v3−v1, v4−v1] as the columns of a matrix; nullopt when degenerate.
std::optional<glm::dmat3> edgeFrame(const TriangleCorners& c)
{
    if (!isFinite(c))
        return std::nullopt;
    const glm::dvec3 e1 = c[1] - c[0];
    const glm::dvec3 e2 = c[2] - c[0];
    const glm::dvec3 normal = glm::cross(e1, e2);
    const double longest = std::max({glm::dot(e1, e1), glm::dot(e2, e2), glm::dot(e2 - e1, e2 - e1)});
    const double area2 = glm::length(normal);
    if (!(area2 > kDegenerateRatio * longest) || !(area2 > 0.0))
        return std::nullopt;
    return glm::dmat3(e1, e2, normal / std::sqrt(area2));
}

} // namespace

glm::dvec3 fourthVertex(const TriangleCorners& c)
{
    const glm::dvec3 normal = glm::cross(c[1] - c[0], c[2] - c[0]);
    const double length = glm::length(normal);
    return length > 0.0 ? c[0] + normal / std::sqrt(length) : c[0];
}

std::optional<glm::dmat3> deformationGradient(const TriangleCorners& reference, const TriangleCorners& deformed)
{
    const std::optional<glm::dmat3> from = edgeFrame(reference);
    const std::optional<glm::dmat3> to = edgeFrame(deformed);
    if (!from || !to)
        return std::nullopt;
    return *to * glm::inverse(*from);
}

glm::dmat3 polarRotation(const glm::dmat3& x)
{
    Eigen::Matrix3d m;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            m(r, c) = x[c][r]; // glm is column-major: x[column][row]
    const Eigen::JacobiSVD<Eigen::Matrix3d, Eigen::NoQRPreconditioner> svd(m,
                                                                           Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d u = svd.matrixU();
    const Eigen::Matrix3d v = svd.matrixV();
    if ((u * v.transpose()).determinant() < 0.0)
        u.col(2) *= -1.0; // singular values are sorted decreasingly: column 2 is the smallest
    const Eigen::Matrix3d r = u * v.transpose();
    glm::dmat3 result;
    for (int row = 0; row < 3; ++row)
        for (int c = 0; c < 3; ++c)
            result[c][row] = r(row, c);
    return result;
}

double rotationAngle(const glm::dmat3& r)
{
    // R[column][row]; the axial vector of R − Rᵀ has length 2·sin θ.
    const glm::dvec3 axial(r[1][2] - r[2][1], r[2][0] - r[0][2], r[0][1] - r[1][0]);
    const double cosine = 0.5 * (r[0][0] + r[1][1] + r[2][2] - 1.0);
    return std::atan2(0.5 * glm::length(axial), cosine);
}

std::vector<double> faceRotationAngles(std::span<const glm::vec3> reference, std::span<const glm::vec3> deformed,
                                       std::span<const glm::uvec3> triangles)
{
    std::vector<double> angles(triangles.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t f = 0; f < triangles.size(); ++f) {
        const glm::uvec3& t = triangles[f];
        const TriangleCorners from{glm::dvec3(reference[t.x]), glm::dvec3(reference[t.y]), glm::dvec3(reference[t.z])};
        const TriangleCorners to{glm::dvec3(deformed[t.x]), glm::dvec3(deformed[t.y]), glm::dvec3(deformed[t.z])};
        if (const std::optional<glm::dmat3> x = deformationGradient(from, to))
            angles[f] = rotationAngle(polarRotation(*x));
    }
    return angles;
}

std::vector<double> vertexRotationAngles(std::span<const double> faceAngles, std::span<const glm::uvec3> triangles,
                                         std::span<const glm::vec3> reference, std::size_t vertexCount,
                                         VertexAveraging averaging)
{
    std::vector<double> sum(vertexCount, 0.0);
    std::vector<double> weight(vertexCount, 0.0);
    for (std::size_t f = 0; f < triangles.size(); ++f) {
        if (std::isnan(faceAngles[f]))
            continue;
        const glm::uvec3& t = triangles[f];
        double w = 1.0;
        if (averaging == VertexAveraging::AreaWeighted)
            w = 0.5 * glm::length(glm::cross(glm::dvec3(reference[t.y]) - glm::dvec3(reference[t.x]),
                                             glm::dvec3(reference[t.z]) - glm::dvec3(reference[t.x])));
        for (int c = 0; c < 3; ++c) {
            sum[t[c]] += w * faceAngles[f];
            weight[t[c]] += w;
        }
    }
    for (std::size_t v = 0; v < vertexCount; ++v)
        sum[v] = weight[v] > 0.0 ? sum[v] / weight[v] : 0.0;
    return sum;
}

} // namespace trimlab
