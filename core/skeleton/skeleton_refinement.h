#pragma once
/// \file
/// Refinement of the curve skeleton (Berenguer & Moreno III.C): each node moves to the
/// centroid of the ORIGINAL positions of the vertices it absorbed (its region Π_k,
/// eq. 11), but only when that centroid lies inside the mesh — the paper's fix for
/// regions whose centroid falls outside the model (Au et al. move unconditionally).

#include "core/skeleton/point_in_mesh.h"
#include "core/skeleton/skeleton.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <span>

namespace trimlab {

/// Moves the nodes of `curve` in place as described above; `originalPositions` (#V) are
/// the input mesh's positions, `inside` tests against that mesh. Nodes whose region is
/// empty, or whose centroid is outside, keep their position. Returns the number of
/// nodes moved. Throws std::invalid_argument if vertexNode and originalPositions differ
/// in size or a vertexNode entry is out of range.
std::size_t refineSkeleton(CurveSkeleton& curve, std::span<const glm::dvec3> originalPositions,
                           const PointInMesh& inside);

} // namespace trimlab
