#pragma once
/// \file
/// The winding numbers of the cells of a refined arrangement (refined_soup.h): the space
/// on each side of every face, per object. Around every edge the faces are sorted by
/// angle (exactly); the two faces bounding each wedge look into the same cell, so a
/// union-find of face sides gathers the sides of each cell's boundary pieces. Across a
/// face the winding grows by the face's delta from front to back, which fixes the
/// windings inside each connected piece of the arrangement up to one offset; one exact
/// ray to infinity per piece fixes that. Internal to core/solid.

#include "core/solid/refined_soup.h"

#include <cstddef>
#include <vector>

namespace trimlab::solid {

struct CellWindings {
    /// front[f][o]: object o's winding number just in front of face f; behind it is
    /// front[f][o] + faces[f].delta[o].
    std::vector<std::vector<int>> front;
    std::size_t boundaryPieces = 0; ///< union-find groups of face sides
    std::size_t components = 0;     ///< connected pieces of the arrangement (one ray each)
    /// Faces whose two sides the union-find put in one group with different windings:
    /// 0 unless the input was not closed (then the windings are not defined).
    std::size_t contradictions = 0;
    std::size_t sortedEdges = 0;                       ///< edges where more than two faces meet
    double wedgesMs = 0.0, walkMs = 0.0, raysMs = 0.0; ///< the stages' times (exact_profile.h)
};

[[nodiscard]] CellWindings cellWindings(const RefinedSoup& soup, const TaskControl& control);

} // namespace trimlab::solid
