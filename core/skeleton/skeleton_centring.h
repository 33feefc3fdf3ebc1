#pragma once
/// \file
/// The last step of placing curve-skeleton nodes, so that they are centred: each node
/// moves, a few times over, to the midpoint of the chord of the solid through it towards
/// its nearest wall (among antipodal ray pairs in a fixed set of directions, the pair
/// whose nearer hit is nearest). In a round limb that chord is the diameter through the
/// node, so one move puts the node on the axis; in other sections the moves climb the
/// distance to the surface towards the centre of the largest ball that fits — the medial
/// axis. Along a limb nothing moves (the nearest wall is across it). The chord's ends are
/// the first surface crossings from the node, so the segment between them, and its
/// midpoint, lie inside. (The shortest chord would not do: through any point of a disc
/// the shortest chord is the one that point bisects.) Region chord midpoints
/// (skeleton_refinement.h) put a node near the centre of the section it absorbed; this
/// removes the offset a one-sided or unevenly sampled region leaves.

#include "core/skeleton/point_in_mesh.h"
#include "core/skeleton/skeleton.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace trimlab {

struct CentringOptions {
    int directions = 48; ///< antipodal pairs tried per node (a Fibonacci half-sphere)
    int rounds = 3;      ///< moves per node
    /// Leaves stay where leaf_extension.h put them: near a tip the nearest wall is the tip
    /// itself, and each move would pull the leaf back along its limb (more rounds, shorter
    /// limbs: the fish's fins lost a third of their coverage). centreLeavesAcrossTheirBones
    /// centres them across their limbs only.
    bool keepLeaves = true;
};

/// Moves every node of `curve` that lies inside `solid` as described above; a node
/// outside, or where a chord it traces finds no surface at an end (the mesh is open
/// there), stays, and so does node k
/// where keep[k] is nonzero (`keep` empty, or one entry per node: the chains
/// medial_chain_routing.h lays along the medial axis need no centring). Returns how many
/// nodes moved. Throws std::invalid_argument when keep has another size. Parallel over
/// nodes.
std::size_t centreOnNearestWallChords(CurveSkeleton& curve, const PointInMesh& solid,
                                      const CentringOptions& options = {}, const std::vector<char>& keep = {});

/// Moves every leaf of `curve` (a node of degree 1) across its bone, `options.rounds`
/// times, to the midpoint of its chord towards the nearest wall among 16 directions in the
/// plane square to the bone (the bone from its neighbour to the leaf): the nearest wall is
/// then a side of its limb, never the tip's cap, so the leaf reaches the limb's axis
/// without being pulled back along it (why centreOnNearestWallChords keeps leaves). A leaf
/// outside `solid`, or a move that would put it or its bone outside, stays. Without it the
/// leaves are the worst-centred nodes of a curve
/// (docs/measurements/2026-11-29-skeleton-stages.md). Returns the leaves moved. Parallel
/// over nodes.
std::size_t centreLeavesAcrossTheirBones(CurveSkeleton& curve, const PointInMesh& solid,
                                         const CentringOptions& options = {});

/// One leaf of centreLeavesAcrossTheirBones: where `leaf`, on a bone from `parent`, moves in
/// `rounds` moves (`leaf` itself where it is outside `solid` or no move is possible).
[[nodiscard]] glm::dvec3 leafCentredAcrossItsBone(const glm::dvec3& parent, const glm::dvec3& leaf,
                                                  const PointInMesh& solid, int rounds);

} // namespace trimlab
