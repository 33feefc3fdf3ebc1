#pragma once
/// \file
/// The point of a triangle mesh's surface closest to a query point: how a stroke given
/// by a bare position (a hand-written script) grabs the surface.

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>

namespace trimlab::deform {

/// A point on one triangle of a mesh.
struct SurfacePoint {
    glm::dvec3 point{0.0};      ///< object space
    std::uint32_t triangle = 0; ///< index into the triangle list
    double distance = 0.0;      ///< Euclidean distance from the query
};

/// Closest point of triangle (a, b, c) to `q`. Degenerate triangles (zero area, a
/// segment or a point) give the closest point of their edges.
[[nodiscard]] glm::dvec3 closestPointOnTriangle(const glm::dvec3& q, const glm::dvec3& a, const glm::dvec3& b,
                                                const glm::dvec3& c);

/// Closest surface point to `query` over every triangle (#F×3 indices into #V
/// `positions`, all in range). Brute force with a bounding-box rejection per triangle:
/// a few milliseconds for 100k triangles, once per stroke. Ties go to the lowest
/// triangle index, so the result is deterministic. Throws std::invalid_argument when
/// there are no triangles or `query` is not finite.
[[nodiscard]] SurfacePoint closestSurfacePoint(std::span<const glm::vec3> positions,
                                               std::span<const glm::uvec3> triangles, const glm::dvec3& query);

} // namespace trimlab::deform
