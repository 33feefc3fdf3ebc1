#pragma once
/// \file
/// The exact arrangement of a soup of triangles: every triangle split along all its
/// intersections with the others, so that the pieces meet only at shared edges and
/// vertices. Written here, on CGAL's exact kernel, box intersection and constrained
/// triangulation, instead of CGAL 5.5's experimental autorefinement, which refuses inputs
/// that real meshes contain (a vertex of one triangle on another's edge, as on the shared
/// cow and diplodocus, and coplanar overlaps three at a time). Internal to core/solid.
///
/// Method: candidate pairs by their bounding boxes; the input's corners are doubles, so
/// exact predicates on those doubles clear most pairs without a construction (on every
/// core); for the rest the exact intersection
/// (nothing, a point, a segment, or a coplanar overlap); triangles that overlap in a
/// plane form one group, every group (a lone triangle too) is triangulated once in its
/// plane with its edges and everything that meets it as constraints, and every piece of
/// that triangulation is given to each member that covers it. So coplanar overlaps come
/// out as identical pieces (which the caller merges), never as two different
/// triangulations of one area; and a point where three triangles meet is computed in each
/// of them exactly, hence equal.

#include "core/solid/exact_kernel.h"
#include "core/solid/exact_profile.h"
#include "core/util/task_control.h"

#include <array>
#include <cstddef>
#include <vector>

namespace trimlab::solid {

struct ArrangedTriangle {
    std::array<ExactPoint, 3> corners; ///< in the orientation of the source triangle
    std::size_t source = 0;            ///< index of the input triangle it is part of
};

/// Splits non-degenerate `triangles` along their intersections. Every output piece lies
/// in its source triangle and runs the same way round; the pieces of one source tile it.
/// Every corner must be a double (an exact point made from doubles, as refineScene makes
/// them; std::invalid_argument otherwise). The result, its order included (pieces by
/// source, each source's by its corners in lexicographic order), does not depend on the
/// number of cores or on their timing. Checks `control` for cancellation (throws OperationCancelled); adds its sizes
/// and times to `profile` when given.
[[nodiscard]] std::vector<ArrangedTriangle> arrangeTriangles(const std::vector<std::array<ExactPoint, 3>>& triangles,
                                                             const TaskControl& control,
                                                             ExactProfile* profile = nullptr);

} // namespace trimlab::solid
