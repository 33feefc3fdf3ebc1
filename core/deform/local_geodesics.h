#pragma once
/// \file
/// Geodesic distances from a surface point within a radius, computed on the local region
/// only: the cost grows with the number of vertices within the radius, not with the mesh.

#include "core/deform/brush_topology.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace trimlab::deform {

/// A vertex with a known starting distance (e.g. a corner of the anchor triangle with its
/// Euclidean distance to the anchor).
struct GeodesicSeed {
    std::uint32_t vertex = 0;
    double distance = 0.0;
};

/// Vertices with distance < radius, sorted ascending, with their distances.
struct LocalDistances {
    std::vector<std::uint32_t> vertices;
    std::vector<double> distances; ///< per entry of `vertices`, in position units
};

/// Approximate geodesic distances from the seeds, for the vertices closer than `radius`.
///
/// A Dijkstra-ordered front (fixed order: ties broken by vertex index, so the result is
/// deterministic) that relaxes both along edges and across triangles: when two corners
/// of a triangle are settled, their distances place a virtual point source in the
/// triangle's plane unfolded across their edge (the triangle update of fast marching on
/// triangulated domains), and the third corner gets its straight-line distance to that
/// source when the line enters through the edge. Across right and obtuse triangles that
/// value can be smaller than the front (the edge's far corner settles after the third
/// corner did, from edges alone), so a settled vertex is reopened when a triangle update
/// improves it by more than rounding (label-correcting).
/// Accuracy: edge paths alone overestimate by up to 8% even on a regular grid; with the
/// triangle update, distances on a flat mesh from a point source are exact up to
/// rounding on a regular grid and within 1% on a jittered one (measured 0.3%), and on
/// the unit icosphere within 1% of the great-circle distance (measured 0.14%); the tests
/// hold those bounds.
///
/// Only vertices whose distance is < radius are ever queued; the work and memory are
/// proportional to them and their one-rings. `positions` holds #V points, seeds must be
/// in range (std::invalid_argument otherwise); seeds with distance >= radius are ignored.
[[nodiscard]] LocalDistances localGeodesicDistances(const BrushTopology& topology, std::span<const glm::vec3> positions,
                                                    std::span<const GeodesicSeed> seeds, double radius);

/// Distance at corner c of triangle (a, b, c) from the point source that is `da` from a
/// and `db` from b and lies on the other side of edge ab than c (the triangle unfolded
/// into its plane). Returns +infinity when no such source exists (da, db and |ab| violate
/// the triangle inequality), when the triangle is degenerate, or when the straight line
/// from the source to c does not cross the segment ab (then edge paths are the answer).
[[nodiscard]] double unfoldedDistance(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, double da,
                                      double db);

} // namespace trimlab::deform
