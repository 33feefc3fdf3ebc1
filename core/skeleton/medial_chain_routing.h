#pragma once
/// \file
/// Chains of the curve skeleton laid along the medial axis, so that the curve is centred
/// and about as long as the shape's, not several times it. The resampling centres each
/// slice of a chain on its own, and where a chain crosses a thick or flat part (a cow's
/// torso, which the contraction leaves as a web between the feet) neighbouring slices'
/// centres land on different places of the medial sheet: the chain zig-zags, and every
/// straight edge between two sheet points cuts through the slab off its middle.
///
/// Here every chain between two nodes of degree other than 2 is replaced by the cheapest
/// path between its two ends through a graph of medial points: the inward chord midpoints
/// (skeleton_refinement.h), one per cell of a grid (the midpoint of the longest chord
/// through the cell), each with the radius of its empty ball (the distance to the nearest
/// mesh vertex). A point is joined to its nearest few within three cells that lie in its
/// ball or in whose ball it lies, so the segment between them is inside; a step costs its length over the square of
/// the balls' mean radius, so the path keeps to the middle, where the balls are largest —
/// the penalised shortest path of TEASAR-like skeletonisers. The path is smoothed, and the
/// chain's nodes are spread along it by arc length, in their order; more nodes are added
/// where the steps would exceed the spacing. Each old node keeps its region (the vertices
/// it absorbed move with it along the chain); added nodes absorb none.
///
/// Only chains that are bridges of the graph are routed: the two chains around a hole
/// would find the same cheapest path and the loop would fold onto itself. A chain stays as
/// it was when an end sees no medial point inside, no path joins its ends, an edge of the
/// routed chain would leave the solid, or the vertices its nodes absorbed would end more
/// than 5 % farther from the curve and farther than the mesh's worst-covered vertex was: a
/// chain that folds (on homer, from the neck up into the head and back to a junction just
/// above where it started) covers what the cheapest path between its ends would cut off.
/// If the worst-covered vertex itself would end more than 5 % farther, nothing is routed.

#include "core/mesh/triangle_mesh.h"
#include "core/skeleton/point_in_mesh.h"
#include "core/skeleton/skeleton.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>
#include <vector>

namespace trimlab {

/// Per node of `curve`: 1 for the interior nodes of the chains routeChainsAlongMedialAxis
/// would route (those of bridge chains), which the centring can leave to it.
[[nodiscard]] std::vector<char> routableChainInteriors(const CurveSkeleton& curve);

/// What routeChainsAlongMedialAxis did.
struct ChainRouting {
    std::size_t chains = 0;   ///< chains routed
    std::vector<char> placed; ///< per node of the routed curve: 1 where the routing placed it
};

/// Routes the chains of `curve` as described above; `midpoints` as
/// inwardChordMidpoints(mesh, inside), `spacing` the resampling's (the grid's cell is half
/// of it). Edges stay sorted, first < second. Throws std::invalid_argument when
/// vertexNode, the mesh and midpoints disagree in size or spacing is not positive.
ChainRouting routeChainsAlongMedialAxis(CurveSkeleton& curve, const TriangleMesh& mesh,
                                        const std::vector<std::optional<glm::dvec3>>& midpoints,
                                        const PointInMesh& inside, double spacing);

} // namespace trimlab
