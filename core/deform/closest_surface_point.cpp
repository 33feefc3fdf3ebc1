#include "core/deform/closest_surface_point.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace trimlab::deform {

namespace {

glm::dvec3 closestPointOnSegment(const glm::dvec3& q, const glm::dvec3& a, const glm::dvec3& b)
{
    const glm::dvec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    if (len2 == 0.0)
        return a;
    return a + glm::clamp(glm::dot(q - a, ab) / len2, 0.0, 1.0) * ab;
}

double distance2(const glm::dvec3& p, const glm::dvec3& q)
{
    const glm::dvec3 d = p - q;
    return glm::dot(d, d);
}

// Fallback for slivers: the best of the three edges.
glm::dvec3 closestPointOnEdges(const glm::dvec3& q, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
    glm::dvec3 best = closestPointOnSegment(q, a, b);
    for (const glm::dvec3& p : {closestPointOnSegment(q, b, c), closestPointOnSegment(q, c, a)}) {
        if (distance2(p, q) < distance2(best, q))
            best = p;
    }
    return best;
}

// Squared distance from q to the bounding box of (a, b, c): a lower bound of the
// distance to the triangle that costs a fraction of the exact test.
double boxDistance2(const glm::dvec3& q, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
    const glm::dvec3 lo = glm::min(a, glm::min(b, c));
    const glm::dvec3 hi = glm::max(a, glm::max(b, c));
    const glm::dvec3 outside = glm::max(lo - q, glm::max(q - hi, glm::dvec3(0.0)));
    return glm::dot(outside, outside);
}

} // namespace

// Classifies q by the Voronoi regions of the triangle's features (3 corners, 3 edges,
// the face) using the dot products of q − corner with the edge vectors, and projects
// onto the feature whose region holds q.
glm::dvec3 closestPointOnTriangle(const glm::dvec3& q, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
    const glm::dvec3 ab = b - a, ac = c - a;
    if (glm::dot(glm::cross(ab, ac), glm::cross(ab, ac)) == 0.0)
        return closestPointOnEdges(q, a, b, c);

    const glm::dvec3 aq = q - a;
    const double d1 = glm::dot(ab, aq), d2 = glm::dot(ac, aq);
    if (d1 <= 0.0 && d2 <= 0.0)
        return a;
    const glm::dvec3 bq = q - b;
    const double d3 = glm::dot(ab, bq), d4 = glm::dot(ac, bq);
    if (d3 >= 0.0 && d4 <= d3)
        return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
        return a + (d1 / (d1 - d3)) * ab;
    const glm::dvec3 cq = q - c;
    const double d5 = glm::dot(ab, cq), d6 = glm::dot(ac, cq);
    if (d6 >= 0.0 && d5 <= d6)
        return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
        return a + (d2 / (d2 - d6)) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
        return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    const double sum = va + vb + vc;
    if (!(sum > 0.0))
        return closestPointOnEdges(q, a, b, c); // rounding on a near-sliver
    return a + (vb / sum) * ab + (vc / sum) * ac;
}

SurfacePoint closestSurfacePoint(std::span<const glm::vec3> positions, std::span<const glm::uvec3> triangles,
                                 const glm::dvec3& query)
{
    if (triangles.empty())
        throw std::invalid_argument("closestSurfacePoint: the mesh has no triangles");
    if (!std::isfinite(query.x) || !std::isfinite(query.y) || !std::isfinite(query.z))
        throw std::invalid_argument("closestSurfacePoint: the query point is not finite");

    SurfacePoint best;
    double best2 = std::numeric_limits<double>::infinity();
    for (std::size_t f = 0; f < triangles.size(); ++f) {
        const glm::uvec3& t = triangles[f];
        const glm::dvec3 a(positions[t.x]), b(positions[t.y]), c(positions[t.z]);
        if (boxDistance2(query, a, b, c) >= best2)
            continue;
        const glm::dvec3 p = closestPointOnTriangle(query, a, b, c);
        const double d2 = distance2(p, query);
        if (d2 < best2) {
            best2 = d2;
            best.point = p;
            best.triangle = static_cast<std::uint32_t>(f);
        }
    }
    best.distance = std::sqrt(best2);
    return best;
}

} // namespace trimlab::deform
