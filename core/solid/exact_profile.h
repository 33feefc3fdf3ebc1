#pragma once
/// \file
/// Where the exact export spends its time, and the sizes that drive each stage: filled
/// by the arrangement (triangle_arrangement.h, refined_soup.h) and the cell windings
/// (cell_windings.h), carried in TrimmedSolidStats, printed by bench_exact. Milliseconds
/// are wall-clock time of the stage as run (on as many threads as it uses).

#include <cstddef>

namespace trimlab {

struct ExactProfile {
    std::size_t candidatePairs = 0;   ///< triangle pairs whose bounding boxes (and parts' boxes) overlap
    std::size_t constructedPairs = 0; ///< pairs whose intersection was constructed exactly
    std::size_t splitTriangles = 0;   ///< input triangles triangulated with what others leave on them
    std::size_t coplanarGroups = 0;   ///< groups of two or more triangles overlapping in one plane
    std::size_t largestCoplanarGroup = 0;
    std::size_t sortedEdges = 0; ///< edges where more than two faces meet (sorted by angle)
    std::size_t rays = 0;        ///< rays cast to fix the windings of connected pieces

    double pairsMs = 0.0;       ///< candidate pairs by bounding boxes, decided by predicates on the input
    double constructMs = 0.0;   ///< exact intersections of the remaining pairs
    double triangulateMs = 0.0; ///< constrained triangulation of the split triangles
    double mergeMs = 0.0;       ///< equal points and coincident faces merged
    double wedgesMs = 0.0;      ///< faces around edges sorted, face sides joined into cells
    double walkMs = 0.0;        ///< relative windings across faces
    double raysMs = 0.0;        ///< the absolute windings by rays
};

} // namespace trimlab
