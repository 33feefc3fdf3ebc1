#pragma once
/// \file
/// Branch recovery, so that every limb has a bone near it. The contraction can draw a
/// short limb into the body along its length before its sections shrink to a curve (legs
/// of a low-resolution cow, a koala's ears, a wrist), and then no branch of the curve
/// skeleton reaches it: its vertices are left to a bone in the body, and the maximum
/// coverage distance is the limb's length.
///
/// Such a limb shows on the surface: a vertex of a limb that has its branch lies about one
/// medial-ball radius from the skeleton (the ball's centre is on the branch), while a vertex
/// of a lost limb lies many radii away. Vertices farther than kUncoveredRatio radii are
/// grouped into connected patches of the mesh (without a ball — no inward chord, or a
/// centre outside — a vertex is judged by its half-chord alone). A patch grows out from
/// where it meets the covered surface (the limb's base); its depth — the longest surface
/// path from that border — is the limb's length. A patch at least kMinDepthRatio radii
/// deep gets a branch:
/// the patch is cut into slices by that path length, and each slice into its connected
/// pieces (where the part forks — a cow's head into its ears and horns — a slice has a
/// piece in each fork, and the branch forks with it); each piece's node is the mean of its
/// vertices' ball centres (the limb's axis, whatever side of the limb the vertices are on),
/// joined to the node of the piece of the slice before that it shares most mesh edges with.
/// A last piece far smaller than the one before it (a crescent along one rim of a flat or
/// slanted end) joins that one. The first slice's pieces join the nearest skeleton node
/// whose segment to them stays inside; a piece whose edge would leave the solid is left out
/// with everything beyond it. A piece's vertices join its node's region. A patch that is
/// wide but shallow (the flank of a flat body) has no depth and gets nothing. Forking the
/// branch with the pieces keeps a head with ears and horns from getting one chain up its
/// middle, which covers the ears no better and is off-centre in the head (the measurements:
/// docs/measurements/2026-11-29-skeleton-stages.md).

#include "core/mesh/triangle_mesh.h"
#include "core/skeleton/point_in_mesh.h"
#include "core/skeleton/skeleton.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>
#include <vector>

namespace trimlab {

/// A vertex farther than this many ball radii from every skeleton edge is uncovered.
inline constexpr double kUncoveredRatio = 2.0;
/// A patch of uncovered vertices gets a branch when it is at least this many mean ball
/// radii deep.
inline constexpr double kMinDepthRatio = 2.0;
/// Patches of fewer vertices are noise (a bump, a spike of the tessellation).
inline constexpr std::size_t kMinPatchVertices = 8;

/// Adds the branches described above to `curve` (nodes appended, edges sorted and
/// first < second, vertexNode updated) and returns how many it added. `midpoints` are
/// inwardChordMidpoints(mesh, solid) (skeleton_refinement.h): a vertex farther than
/// kUncoveredRatio half-chords is uncovered without a ball (the half-chord bounds the
/// ball's radius), and balls (shrinking_balls.h) are computed only where patches grow, so
/// a well-covered mesh costs one distance per vertex. `spacing` is the least slice width
/// (a slice is at least the patch's mean ball radius wide). Throws std::invalid_argument
/// when vertexNode, midpoints and the mesh's vertices differ in number or spacing is
/// negative.
std::size_t recoverBranches(CurveSkeleton& curve, const TriangleMesh& mesh,
                            const std::vector<std::optional<glm::dvec3>>& midpoints, const PointInMesh& solid,
                            double spacing);

} // namespace trimlab
