#include "core/animation/segment_colors.h"

#include "core/animation/segment_coloring.h"
#include "core/image/packed_rgba8.h"

#include <algorithm>

namespace trimlab {

void SegmentColors::reset()
{
    m_labeling = {};
    m_colors.clear();
}

void SegmentColors::show(const VertexGraph& graph, std::span<const double> areas, VertexLabeling labeling)
{
    if (m_labeling.labels.size() == labeling.labels.size() && !m_labeling.labels.empty())
        m_colors = propagateColors(graph, areas, m_labeling, m_colors, labeling);
    else
        m_colors = colorSegments(graph, labeling, areas);
    m_labeling = std::move(labeling);
}

void SegmentColors::showColored(VertexLabeling labeling, std::vector<WheelColor> colors)
{
    m_labeling = std::move(labeling);
    m_colors = std::move(colors);
}

std::vector<std::uint32_t> vertexRgba8(const VertexLabeling& labeling, std::span<const WheelColor> colors)
{
    std::vector<std::uint32_t> packed(colors.size());
    std::transform(colors.begin(), colors.end(), packed.begin(),
                   [](const WheelColor& color) { return packRgba8(color.rgb()); });
    std::vector<std::uint32_t> perVertex(labeling.labels.size());
    std::transform(labeling.labels.begin(), labeling.labels.end(), perVertex.begin(),
                   [&](std::uint32_t label) { return packed[label]; });
    return perVertex;
}

} // namespace trimlab
