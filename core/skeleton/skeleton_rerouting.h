#pragma once
/// \file
/// The last repair of the curve skeleton: an edge that still crosses the surface after
/// the bisections (skeleton_resampling.h, splitEdgesLeaving) joins two parts of the solid
/// that only touch — a penguin's flipper lying against its body, a scorpion's leg against
/// the next one. The contraction merged them across the gap, so no point between the two
/// ends is inside and bisecting cannot help: the way from one part to the other goes
/// around, through where they really join. Such an edge is replaced by that way: the
/// shortest path over the mesh's edges between the surface vertices nearest to its ends,
/// each vertex on it replaced by the midpoint of its inward chord (a point in the middle
/// of the part under it), thinned greedily to the farthest point still visible inside.
/// The new nodes absorb no vertices (as the bisections' do). An edge for which no such
/// path stays inside is kept as it is, and counted.

#include "core/skeleton/point_in_mesh.h"
#include "core/skeleton/skeleton.h"
#include "core/mesh/triangle_mesh.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>
#include <vector>

namespace trimlab {

struct ReroutingResult {
    std::size_t rerouted = 0; ///< leaving edges replaced by an inside path
    std::size_t kept = 0;     ///< leaving edges left as they were (no inside path found)
    std::size_t nodesAdded = 0;
};

/// Reroutes every edge of `curve` that leaves the solid (segmentInside), as above.
/// `mesh` is the input mesh, `inside` built from it, `midpoints` its
/// inwardChordMidpoints. Edges stay sorted, first < second. Throws std::invalid_argument
/// when midpoints and the mesh's vertices differ in number.
ReroutingResult rerouteLeavingEdges(CurveSkeleton& curve, const TriangleMesh& mesh,
                                    const std::vector<std::optional<glm::dvec3>>& midpoints, const PointInMesh& inside);

} // namespace trimlab
