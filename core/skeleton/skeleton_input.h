#pragma once
/// \file
/// What skeleton extraction by mesh contraction accepts (Berenguer & Moreno III.A): one
/// closed, manifold, connected surface with finite coordinates. Contraction needs a closed
/// surface (an open one shrinks from its border instead of towards its medial curve), the
/// edge-collapse simplification needs manifold one-rings, and a second component would
/// contract into a second skeleton that no rig can join.

#include "core/mesh/triangle_mesh.h"

#include <stdexcept>
#include <string>

namespace trimlab {

/// A mesh that skeleton extraction refuses. `what()` names the first problem (the first
/// boundary or non-manifold edge by its vertices, the components with their vertex
/// counts, the first bad vertex or face) and says what to do about it.
class SkeletonInputError : public std::runtime_error {
public:
    explicit SkeletonInputError(const std::string& reason) : std::runtime_error(reason) {}
};

/// Throws SkeletonInputError unless `mesh` has triangles, only in-range indices, finite
/// coordinates, no face with a repeated vertex index, no boundary edge, no non-manifold
/// edge or vertex, and exactly one face-connected component. Checked in that order; the
/// message describes the first failing check. Zero-area triangles with three distinct
/// vertices are accepted (the later stages handle them without NaNs), and so are
/// vertices that no triangle uses (they stay where they are and join the nearest node).
/// O(F log F).
void checkSkeletonInput(const TriangleMesh& mesh);

} // namespace trimlab
