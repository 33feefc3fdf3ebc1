#pragma once
/// \file
/// Cap bones, so that a blunt end of the body has a bone near it. A blunt end — a fish's
/// head — contracts into a knot of short chains rather than one limb, and the curve leaves
/// it at a node whose bones run back into the body or sideways along the knot: no leaf
/// points at the cap, so leaf_extension.h has nothing to extend, and the cap's vertices
/// are the farthest from any bone.
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
/// Why the band and one bone per cap: without the restriction to the farthest caps every
/// mesh gets bones and the curve's centring suffers; without the one-bone-per-cap rule a
/// chain past a flat part gets a bone at every node (the measurements:
/// docs/measurements/2026-11-29-skeleton-stages.md).

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
