#pragma once
/// \file
/// p2p-cleaning (thesis 3.1.2, Algorithm 3.2 with the reduction rule 3.1–3.4): the
/// over-segmentation is simplified pose by pose from p_k back to p_1; at pose p_i a
/// segment S_A is absorbed by its largest neighbour S_B when both came from one segment
/// of OS(p_1 … p_{i−1}) that C_i split, and S_A is small (a(S_A) ≤ h·a(C_i cluster of
/// S_A) and a(S_A) ≤ h·a(segment(S_A, i−1))) — a sliver made by slightly different
/// cluster borders rather than a part with its own motion.

#include "core/animation/pose_join.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

/// Everything p2p-cleaning needs from a PoseJoin, reduced to the r segments of the
/// over-segmentation, so that clean(h) no longer depends on the mesh size: a slider over
/// h re-cleans without touching the partitions or the mesh (thesis 3.2.4).
/// Two neighbouring segments S, T satisfy condition 3.3 at exactly one pose: the pose
/// p_i that first separates them (segment(S, i−1) = segment(T, i−1), segment(S, i) ≠
/// segment(T, i)), and merged segments keep the prefix segments of their members up to
/// the pose being cleaned. So every neighbour pair is examined at that one pose only and
/// clean(h) costs O(k + r + |segment adjacencies|) instead of the thesis's O(k·(n + r)).
///
/// Choices where Algorithm 3.2 leaves room (each what an animator moving the h slider
/// would expect):
/// - Areas a(·) are barycentric vertex areas of the rest pose (vertex_areas.h), the
///   same for every pose, so h means the same fraction in every pose.
/// - Within one pose every decision — which segments are small enough (3.1, 3.2), which
///   neighbour is S_B (3.3, 3.4), the areas, which counts as in the thesis: "the area of
///   the new cluster is considered ... to be this of the absorbing cluster S_B" — is made
///   on the segmentation as it stands when the pose begins; then all absorptions of the
///   pose are applied together. The result is therefore independent of the order in
///   which segments are visited (Lemma 3.1). The thesis's sequential loop lets an earlier
///   absorption change a later segment's candidates (S_C next to S_A, S_A absorbed by
///   S_B where S_B is in S_C's cluster: S_C would then never be cleaned), which makes
///   its result order-dependent in such chains; here S_C → S_A → S_B all merge.
/// - S_B is the neighbour of largest area with a(S_B) > a(S_A); ties go to the segment
///   with the smaller first vertex. A merged segment is numbered by its first vertex.
/// - The segment count falls as h grows, but not strictly at every h: a merge at a later
///   pose can make a segment too large to be absorbed (or change its neighbours) at an
///   earlier pose, so a slightly larger h occasionally leaves one or two more segments.
///   Making the rule monotone by construction (merging the results of all smaller h)
///   chains slivers across segments and collapses the segmentation, so it is not done.
/// - h ≤ 0 returns the over-segmentation unchanged (the rule would still merge segments
///   of zero area, which surprises more than it helps); h ≥ 1 makes every segment with a
///   larger eligible neighbour small enough.
class P2pCleaner {
public:
    /// `areas`: #V vertex areas (rest pose). Throws std::invalid_argument on a size
    /// mismatch. O(k·r + |E| log |E|).
    P2pCleaner(const PoseJoin& join, std::span<const double> areas);

    /// The cleaned segmentation for `h` (canonical labels).
    [[nodiscard]] VertexLabeling clean(double h) const;

    /// The same, visiting the segments of each pose in `order` (a permutation of
    /// 0 … r−1; std::invalid_argument otherwise). Exists to test Lemma 3.1: the result
    /// does not depend on it.
    [[nodiscard]] VertexLabeling clean(double h, std::span<const std::uint32_t> order) const;

    /// r = |OS(A)|.
    [[nodiscard]] std::size_t overSegmentCount() const { return m_segmentArea.size(); }
    [[nodiscard]] std::size_t poseCount() const { return m_poses; }

private:
    [[nodiscard]] std::uint32_t levelOf(std::size_t level, std::uint32_t segment) const
    {
        return m_levelOf[level * m_segmentArea.size() + segment];
    }
    [[nodiscard]] std::uint32_t clusterOf(std::size_t pose, std::uint32_t segment) const
    {
        return m_clusterOf[pose * m_segmentArea.size() + segment];
    }
    struct CleaningState;
    void cleanPose(std::size_t pose, double h, CleaningState& state) const;

    std::size_t m_poses = 0;
    std::vector<std::uint32_t> m_vertexSegment;     ///< #V: segment of OS(A)
    std::vector<double> m_segmentArea;              ///< r
    std::vector<std::uint32_t> m_levelOf;           ///< (k+1) × r: segment(S, i)
    std::vector<std::uint32_t> m_clusterOf;         ///< k × r: cav(S)[i]
    std::vector<std::vector<double>> m_levelArea;   ///< per level i: a(segment(·, i))
    std::vector<std::vector<double>> m_clusterArea; ///< per pose: a(C_i cluster)
    /// Neighbouring segments (a < b) grouped by the pose that separates them: the pairs of
    /// pose p are m_pairs[m_pairStart[p] .. m_pairStart[p + 1]).
    std::vector<std::pair<std::uint32_t, std::uint32_t>> m_pairs;
    std::vector<std::size_t> m_pairStart;
};

} // namespace trimlab
