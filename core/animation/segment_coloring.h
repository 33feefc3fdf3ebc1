#pragma once
/// \file
/// Colours for segments and clusters that stay stable over time (thesis 3.2.1): the rest
/// pose is coloured by a breadth-first walk over its clusters with the 12-colour wheel,
/// and every later segmentation inherits colours from the one before by overlap area.
/// The same propagation recolours a segmentation after h changes.

#include "core/animation/color_wheel.h"
#include "core/animation/vertex_graph.h"

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace trimlab {

/// Rest-pose colouring: a breadth-first walk over the label graph (label_adjacency.h),
/// starting at the label of largest area (the thesis picks a random one; the largest
/// makes the result reproducible and gives the body the first colour), neighbours in
/// ascending order; each visited label takes the next palette colour (paletteColor,
/// cycling) that is not nearlySame as the colour of a label within `rings` steps (1: the
/// neighbours, 2: also their neighbours). When the 12 wheel colours all conflict, the
/// palette grows by further rings. Labels in other components of the label graph are
/// walked afterwards, largest first. `areas`: #V vertex areas.
[[nodiscard]] std::vector<WheelColor> colorSegments(const VertexGraph& graph, const VertexLabeling& labeling,
                                                    std::span<const double> areas, int rings = 1);

/// Pose-to-pose propagation from `past` (with `pastColors`, one per past label) to
/// `future` on the same mesh:
/// - overlap areas of every future/past label pair are summed over the vertices;
/// - each past label is "owned" by the future label that covers most of it;
/// - the walk starts at the future label with the largest single overlap; a future label
///   inherits the colour of the first of its past labels, by decreasing overlap, that it
///   owns and whose colour no coloured neighbour has (nearlySame);
/// - otherwise a future label covering one past label takes the next palette colour that
///   no past label has and no future label has taken yet (and no neighbour has; when the
///   rings run out, only the neighbours are avoided), and one covering several takes the
///   mix of its two
///   largest past labels' colours (mixColors: hue mixing, so no grey; near-duplicate and
///   complementary pairs are not mixed) unless that mix is nearlySame or complementary to
///   a neighbour's colour, in which case it also takes a fresh palette colour.
[[nodiscard]] std::vector<WheelColor> propagateColors(const VertexGraph& graph, std::span<const double> areas,
                                                      const VertexLabeling& past,
                                                      std::span<const WheelColor> pastColors,
                                                      const VertexLabeling& future);

/// Colours for a sequence of labelings (pose partitions, variable segmentations):
/// colorSegments for the first, propagateColors from each to the next.
[[nodiscard]] std::vector<std::vector<WheelColor>>
colorSequence(const VertexGraph& graph, std::span<const double> areas, std::span<const VertexLabeling> sequence);

/// RGB in [0, 1] of each colour.
[[nodiscard]] std::vector<glm::vec3> colorsRgb(std::span<const WheelColor> colors);

/// #V RGB colours for display: the colour of each vertex's label.
[[nodiscard]] std::vector<glm::vec3> vertexColors(const VertexLabeling& labeling, std::span<const WheelColor> colors);

} // namespace trimlab
