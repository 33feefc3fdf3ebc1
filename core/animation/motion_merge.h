#pragma once
/// \file
/// Merging segments by how alike they move, so that segments match rigid parts.
/// A segment s moved rigidly from the rest pose to pose t leaves the residual
///     E_s^t = min over rotations R, translations c of Σ_{j∈s} ‖R v_j + c − y_j^t‖²,
/// which depends only on sums over the segment (count, Σv, Σy, Σ y vᵀ, Σ‖v‖², Σ‖y‖²:
/// the Procrustes problem through the SVD of the cross-covariance), so the residual of a
/// union is computed from the two segments' sums without visiting a vertex. Merging the
/// adjacent pair whose union costs least, E_{a∪b} − E_a − E_b summed over poses (Ward's
/// rule for rigid motion), removes first the boundaries between parts that move together;
/// small segments of a rigid part go into that part, not into the largest neighbour.
/// A minimum size comes first: while a segment has fewer than `minVertices` vertices the
/// smallest such segment joins its cheapest neighbour (a vertex or two that move oddly —
/// noise, a spike — would otherwise keep a segment, and a bone, of their own).

#include "core/animation/mesh_animation.h"
#include "core/animation/vertex_graph.h"

#include <cstddef>

namespace trimlab {

/// Merges adjacent segments of `labeling` (#V labels over animation's vertices; `graph`
/// its vertex graph) until `count` remain, by the rule above; a segment with no neighbour
/// (a separate mesh component) may merge with any segment. No change when it has
/// ≤ count. Motions start from animation.restPose. Returns canonical labels.
/// Deterministic: ties go to the smaller labels.
[[nodiscard]] VertexLabeling mergeByMotion(const MeshAnimation& animation, const VertexGraph& graph,
                                           const VertexLabeling& labeling, std::size_t count,
                                           std::size_t minVertices = 0);

} // namespace trimlab
