#include "core/animation/pose_join.h"

#include "core/animation/over_segmentation.h"

#include <algorithm>
#include <stdexcept>

namespace trimlab {

PoseJoin::PoseJoin(std::shared_ptr<const VertexGraph> graph) : m_graph(std::move(graph))
{
    if (!m_graph)
        throw std::invalid_argument("PoseJoin: no graph");
    m_levels.push_back(connectedComponents(*m_graph));
}

void PoseJoin::requireSize(const VertexLabeling& partition) const
{
    if (partition.labels.size() != m_graph->vertexCount())
        throw std::invalid_argument("PoseJoin: the partition has " + std::to_string(partition.labels.size()) +
                                    " labels for " + std::to_string(m_graph->vertexCount()) + " vertices");
}

void PoseJoin::append(VertexLabeling partition)
{
    requireSize(partition);
    VertexLabeling level = joinLabelings(*m_graph, m_levels.back(), partition);
    m_partitions.push_back(std::move(partition));
    m_levels.push_back(std::move(level));
}

void PoseJoin::replace(std::size_t index, VertexLabeling partition)
{
    std::vector<std::pair<std::size_t, VertexLabeling>> one;
    one.emplace_back(index, std::move(partition));
    replace(std::move(one));
}

void PoseJoin::replace(std::vector<std::pair<std::size_t, VertexLabeling>> partitions)
{
    std::size_t first = m_partitions.size();
    for (const auto& [index, partition] : partitions) {
        requireSize(partition);
        if (index >= m_partitions.size())
            throw std::out_of_range("PoseJoin::replace: partition " + std::to_string(index) + " does not exist");
        first = std::min(first, index);
    }
    for (auto& [index, partition] : partitions)
        m_partitions[index] = std::move(partition);
    for (std::size_t i = first; i < m_partitions.size(); ++i)
        m_levels[i + 1] = joinLabelings(*m_graph, m_levels[i], m_partitions[i]);
}

} // namespace trimlab
