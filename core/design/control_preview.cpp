#include "core/design/control_preview.h"

#include <algorithm>
#include <map>

namespace trimlab {

ControlPreview::ControlPreview(EditableSurface& surface, std::vector<glm::vec3> positions)
    : m_surface(surface), m_start(surface.controlPoints()), m_positions(std::move(positions))
{
}

const std::vector<glm::vec3>& ControlPreview::update(std::span<const ControlPointTarget> targets)
{
    std::map<std::uint32_t, glm::dvec3> wanted;
    for (const ControlPointTarget& target : targets)
        wanted[target.index] = target.position;
    std::vector<std::uint32_t> indices = m_moved;
    for (const auto& entry : wanted)
        indices.push_back(entry.first);
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
    std::vector<glm::dvec3> points;
    points.reserve(indices.size());
    for (std::uint32_t index : indices) {
        const auto found = wanted.find(index);
        points.push_back(found != wanted.end() ? found->second : m_start.at(index));
    }
    const std::vector<std::uint32_t> support = m_surface.moveControlPoints(indices, points);
    const std::vector<glm::vec3>& evaluated = m_surface.mesh().positions;
    for (std::uint32_t v : support)
        m_positions[v] = evaluated[v];
    m_moved = std::move(indices);
    return m_positions;
}

} // namespace trimlab
