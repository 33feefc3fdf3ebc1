#pragma once
/// \file
/// How evenly a segmentation spreads the vertices (bones on slivers of a few vertices lower
/// the skinning error little): segment sizes in vertices, smallest first.

#include "core/animation/vertex_graph.h"

#include <cstddef>
#include <vector>

namespace trimlab {

struct SegmentSizes {
    std::vector<std::size_t> sorted; ///< vertices per segment, increasing (labeling.count entries)
    std::size_t underOnePercent = 0; ///< segments with fewer than 1 % of the vertices
};

[[nodiscard]] SegmentSizes segmentSizes(const VertexLabeling& labeling);

} // namespace trimlab
