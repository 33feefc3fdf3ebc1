#pragma once
/// \file
/// The segmentation on screen and its colors, kept stable as it changes (thesis 3.2.1):
/// the first labeling is colored from the rest pose outward (colorSegments); every later
/// one — another h of the slider, the next pose of a stream, a new run — inherits the
/// colors of the one before by overlap area (propagateColors), so segments that merge or
/// persist keep their colors instead of reshuffling the palette.

#include "core/animation/color_wheel.h"
#include "core/animation/vertex_graph.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

class SegmentColors {
public:
    /// Forgets the shown labeling: the next show() colors from scratch. Needed when the
    /// mesh changes (another animation).
    void reset();
    /// Shows `labeling` of the mesh with vertex graph `graph` and #V vertex `areas`,
    /// colored by propagation from the labeling shown before (same #V), or from scratch.
    void show(const VertexGraph& graph, std::span<const double> areas, VertexLabeling labeling);
    /// Shows `labeling` with colors already chosen (one per label), e.g. a variable
    /// segmentation's colorSequence. The next show() propagates from these.
    void showColored(VertexLabeling labeling, std::vector<WheelColor> colors);

    [[nodiscard]] bool empty() const { return m_labeling.labels.empty(); }
    [[nodiscard]] const VertexLabeling& labeling() const { return m_labeling; }
    [[nodiscard]] const std::vector<WheelColor>& colors() const { return m_colors; }

private:
    VertexLabeling m_labeling;
    std::vector<WheelColor> m_colors;
};

/// #V packed colors for ViewportWidget::setVertexColors: the color of each vertex's label
/// (`colors`: one per label).
[[nodiscard]] std::vector<std::uint32_t> vertexRgba8(const VertexLabeling& labeling,
                                                     std::span<const WheelColor> colors);

} // namespace trimlab
