#pragma once
/// \file
/// Cap bones (issue 20: coverage). A blunt end of the body — a fish's head — contracts
/// into a knot of short chains rather than one limb, and the curve leaves it at a node
/// whose bones run back into the body or sideways along the knot: no leaf points at the
/// cap, so leaf_extension.h has nothing to extend, and the cap's vertices are the farthest
/// from any bone (measured: the fish's mouth 0.186 of the diagonal from the curve, CGAL's
/// skeleton 0.157–0.170).
///
/// Such a node shows in its region: the region holds some of the mesh's farthest vertices
/// from the curve (within kCapWorstFraction of the farthest), they lie, on average, more
/// than the cap's own radius ahead of the node (the mean distance from that direction's
/// line of the region's vertices ahead of the node; a chain node's ring of vertices sits
/// around it), and no bone of the node leaves within kCapBoneCone of that direction. At a
/// junction they must also lie beyond kCapBallRatio of its ball (a round hub between limbs
/// is as near as its ball lets it be). The node then gets a new leaf towards its far
/// vertices, placed by the leaf extension's rule (one cap radius short of the farthest
/// vertex ahead, shortened while the bone would leave the solid) and centred across its
/// bone (skeleton_centring.h), when the bone brings the region's farthest vertex at least
/// kMinCapGain nearer to the curve. The farthest caps go first; a region whose far vertices
/// a bone added before has brought below the band gets none (one bone per cap, not one per
/// node of a chain that runs past it).
///
/// Measured (eleventh session, the region's centroid for the direction, its whole width, the
/// ball test at every node): one bone on the fish, its coverage 0.186 → 0.154 of the
/// diagonal (CGAL 0.157–0.170), two on the armadillo after one Loop subdivision, none on
/// the 19 other meshes. Twelfth session (the far vertices' direction, the cap's width, the
/// ball test at junctions only, one bone per cap): bones on 10 of the 21 meshes, the
/// largest distance from the curve down on all 10 — the spot's muzzle and rump 0.1605 →
/// 0.1415 (CGAL 0.146–0.149), the hand 0.131 → 0.104, the stuffed toy 0.154 → 0.131, the
/// armadillo 0.122 → 0.111, after one and two Loop subdivisions 0.136 → 0.122 and 0.130 →
/// 0.117 — and the curves' centring within 0.003 (the spot 0.076 → 0.074, the
/// low-resolution spot 0.091 → 0.094). Without the restriction to the
/// farthest caps every mesh got bones (the fish 10) and the curves' centring lost 0.01;
/// without the one-bone-per-cap rule a chain past a flat part got a bone at every node (the
/// armadillo after one subdivision 21, homer 8).

#include "core/mesh/triangle_mesh.h"
#include "core/skeleton/point_in_mesh.h"
#include "core/skeleton/skeleton.h"

#include <cstddef>

namespace trimlab {

/// A bone within this angle's cosine (60°) of the region's direction already reaches the cap.
inline constexpr double kCapBoneCone = 0.5;
/// A junction's cap's farthest vertex lies farther than this many times the junction's
/// distance to its nearest wall (its ball's radius): within it, the vertex is as near as a
/// round end — a ball-shaped hub between limbs — lets any bone be (the test's star:
/// 0.94–1.14). Chain nodes are not asked: the spot's rump, 1.25 balls from the spine's
/// node nearest it, is the end of a long body, not a hub.
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
