#include "core/skeleton/shrinking_balls.h"

#include "core/util/parallel_for.h"
#include "core/util/point_kd_tree.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

constexpr std::size_t kVertexBlock = 1024;
/// A vertex within this fraction of the squared radius counts as on the sphere: the mesh
/// stores float positions (relative rounding ~6e-8 per coordinate), so the other vertices
/// of a tube's ring lie at the tube's radius only to about 1e-7 of it.
constexpr double kOnSphere = 1e-6;

/// The radius of p's medial ball along the inward unit normal m, shrunk from `radius`.
double shrunkRadius(const PointKdTree& tree, const glm::dvec3& p, const glm::dvec3& m, double radius)
{
    for (int step = 0; step < kMaxBallShrinkSteps; ++step) {
        const glm::dvec3 centre = p + radius * m;
        // The nearest vertex inside the ball, among those seen from the centre at least
        // kMinSeparationDegrees away from p (within the chord 2r·sin(θ/2) of p). One on the
        // sphere does not shrink it (the ball touches the surface there, which is what a
        // medial ball does).
        const double separation = 2.0 * radius * std::sin(0.5 * glm::radians(kMinSeparationDegrees));
        const NearestPoint nearest =
            tree.nearestAwayFrom(centre, radius * radius * (1.0 - kOnSphere), p, separation * separation);
        if (!nearest.found())
            return radius;
        const glm::dvec3 toQ = tree.point(nearest.index) - p;
        const double along = glm::dot(m, toQ);
        // Inside the ball means |q − p|² < 2r·m·(q − p), so `along` > 0 here.
        const double lengthSquared = glm::dot(toQ, toQ);
        if (!(along > 0.0) || !(lengthSquared > 0.0))
            return radius;
        radius = lengthSquared / (2.0 * along);
    }
    return radius;
}

} // namespace

struct ShrinkingBalls::Tree {
    PointKdTree points;
};

ShrinkingBalls::ShrinkingBalls(const TriangleMesh& mesh, const std::vector<std::optional<glm::dvec3>>& midpoints,
                               const PointInMesh& inside)
    : m_mesh(mesh), m_midpoints(midpoints), m_inside(inside)
{
    if (midpoints.size() != mesh.vertexCount())
        throw std::invalid_argument("ShrinkingBalls: " + std::to_string(midpoints.size()) + " midpoints for " +
                                    std::to_string(mesh.vertexCount()) + " vertices");
    m_tree = std::make_unique<Tree>(
        Tree{PointKdTree(std::vector<glm::dvec3>(mesh.positions.begin(), mesh.positions.end()))});
}

ShrinkingBalls::~ShrinkingBalls() = default;

std::optional<glm::dvec3> ShrinkingBalls::centre(std::size_t v) const
{
    if (v >= m_midpoints.size() || !m_midpoints[v])
        return std::nullopt;
    const glm::dvec3 p(m_mesh.positions[v]);
    const glm::dvec3 toMidpoint = *m_midpoints[v] - p;
    const double startRadius = glm::length(toMidpoint);
    if (!(startRadius > 0.0))
        return std::nullopt;
    // The chord runs along the inward normal, so its direction is that normal.
    const glm::dvec3 m = toMidpoint / startRadius;
    const glm::dvec3 centre = p + shrunkRadius(m_tree->points, p, m, startRadius) * m;
    if (!m_inside.contains(centre))
        return std::nullopt;
    return centre;
}

std::vector<std::optional<glm::dvec3>> shrinkingBallCentres(const TriangleMesh& mesh,
                                                            const std::vector<std::optional<glm::dvec3>>& midpoints,
                                                            const PointInMesh& inside)
{
    const ShrinkingBalls balls(mesh, midpoints, inside);
    std::vector<std::optional<glm::dvec3>> centres(mesh.vertexCount());
    const std::size_t blocks = (mesh.vertexCount() + kVertexBlock - 1) / kVertexBlock;
    parallelFor(blocks, 0, [&](std::size_t block) {
        const std::size_t end = std::min(mesh.vertexCount(), (block + 1) * kVertexBlock);
        for (std::size_t v = block * kVertexBlock; v < end; ++v)
            centres[v] = balls.centre(v);
    });
    return centres;
}

} // namespace trimlab
