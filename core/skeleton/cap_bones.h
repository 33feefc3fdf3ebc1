#pragma once
/// \file
/// Cap bones (issue 20: coverage). A blunt end of the body — a fish's head — contracts
/// into a knot of short chains rather than one limb, and the curve leaves it at a node
/// whose bones run back into the body or sideways along the knot: no leaf points at the
/// cap, so leaf_extension.h has nothing to extend, and the cap's vertices are the farthest
/// from any bone (measured: the fish's mouth 0.186 of the diagonal from the curve, CGAL's
/// skeleton 0.157–0.170).
///
/// Such a node shows in its region: the vertices it absorbed lie, on average, more than
/// their own radius ahead of it (a chain node's ring of vertices sits around it), and no
/// bone of the node leaves within kCapBoneCone of that direction. Where that region holds
/// some of the mesh's farthest vertices from the curve (within kCapWorstFraction of the
/// farthest) and they lie beyond kCapBallRatio of the node's ball (a round end — a
/// ball-shaped hub between limbs — is as near as its ball lets it be), the node gets a new
/// leaf in the cap's direction, placed by the leaf extension's rule (one local radius short
/// of the farthest vertex ahead, shortened while the bone would leave the solid), when the
/// bone brings the region's farthest vertex at least kMinCapGain nearer to the curve.
///
/// Measured (eleventh session): one bone on the fish, its coverage 0.186 → 0.154 of the
/// diagonal (CGAL 0.157–0.170), and two on the armadillo after one Loop subdivision, 0.139
/// → 0.136; on the 19 other meshes none. Without the restriction to the farthest caps every
/// mesh got bones (the fish 10) and the curves' centring lost 0.01 (the armadillo after one
/// subdivision then failed against CGAL's).

#include "core/mesh/triangle_mesh.h"
#include "core/skeleton/point_in_mesh.h"
#include "core/skeleton/skeleton.h"

#include <cstddef>

namespace trimlab {

/// A bone within this angle's cosine (60°) of the region's direction already reaches the cap.
inline constexpr double kCapBoneCone = 0.5;
/// A cap's farthest vertex lies farther than this many times the node's distance to its
/// nearest wall (its ball's radius): within it, the vertex is as near as a round end — a
/// ball-shaped hub between limbs — lets any bone be (the test's star: 0.94–1.14; the
/// fish's head 1.76).
inline constexpr double kCapBallRatio = 1.5;
/// Caps whose farthest vertex is nearer the curve than this fraction of the mesh's farthest get none.
inline constexpr double kCapWorstFraction = 0.9;
/// A cap bone must cut the region's largest distance to the curve by at least this fraction.
inline constexpr double kMinCapGain = 0.15;

/// Adds the cap bones described above to `curve` (nodes appended, edges sorted and
/// first < second; the region vertices past the new bone's middle join its leaf). `mesh`
/// holds the regions' original positions. Returns the bones added.
std::size_t addCapBones(CurveSkeleton& curve, const TriangleMesh& mesh, const PointInMesh& solid);

} // namespace trimlab
