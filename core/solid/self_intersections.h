#pragma once
/// \file
/// How often a mesh crosses itself, for Mesh Statistics: the pairs of its triangles that
/// intersect and share no vertex, decided by CGAL's exact predicates on the float
/// positions (no tolerance, so a touching pair counts). Pairs that share a vertex or an
/// edge meet there by construction and are not counted: a fold between neighbours shows
/// in the count of the triangles around it. A surface that crosses itself is what the
/// trim rules are for, so the count says how much there is to trim, not a defect.

#include "core/mesh/triangle_mesh.h"
#include "core/util/task_control.h"

#include <cstddef>

namespace trimlab {

struct SelfIntersections {
    std::size_t pairs = 0;     ///< intersecting triangle pairs that share no vertex
    std::size_t triangles = 0; ///< triangles in at least one such pair
};

/// The self-intersections of `mesh` (world or object space alike). Degenerate triangles
/// (a repeated index or zero area) are skipped. Checks `control` between candidate
/// pairs (throws OperationCancelled).
[[nodiscard]] SelfIntersections selfIntersections(const TriangleMesh& mesh, const TaskControl& control = {});

} // namespace trimlab
