#include "core/animation/vertex_graph.h"

#include <algorithm>
#include <unordered_map>

namespace trimlab {

VertexGraph buildVertexGraph(std::size_t vertexCount, std::span<const glm::uvec3> triangles)
{
    std::vector<std::uint64_t> directed;
    directed.reserve(6 * triangles.size());
    for (const glm::uvec3& t : triangles) {
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t a = t[c];
            const std::uint32_t b = t[(c + 1) % 3];
            if (a == b)
                continue;
            directed.push_back((std::uint64_t(a) << 32) | b);
            directed.push_back((std::uint64_t(b) << 32) | a);
        }
    }
    std::sort(directed.begin(), directed.end());
    directed.erase(std::unique(directed.begin(), directed.end()), directed.end());
    VertexGraph graph;
    graph.offsets.assign(vertexCount + 1, 0);
    graph.neighbors.reserve(directed.size());
    for (const std::uint64_t e : directed) {
        ++graph.offsets[(e >> 32) + 1];
        graph.neighbors.push_back(std::uint32_t(e));
    }
    for (std::size_t v = 0; v < vertexCount; ++v)
        graph.offsets[v + 1] += graph.offsets[v];
    return graph;
}

VertexLabeling connectedComponents(const VertexGraph& graph)
{
    constexpr std::uint32_t kNone = UINT32_MAX;
    VertexLabeling result;
    result.labels.assign(graph.vertexCount(), kNone);
    std::vector<std::uint32_t> queue;
    for (std::size_t start = 0; start < graph.vertexCount(); ++start) {
        if (result.labels[start] != kNone)
            continue;
        const std::uint32_t label = result.count++;
        result.labels[start] = label;
        queue.assign(1, std::uint32_t(start));
        for (std::size_t head = 0; head < queue.size(); ++head) {
            for (const std::uint32_t n : graph.neighborsOf(queue[head])) {
                if (result.labels[n] == kNone) {
                    result.labels[n] = label;
                    queue.push_back(n);
                }
            }
        }
    }
    return result;
}

VertexLabeling canonicalLabeling(std::span<const std::uint32_t> labels)
{
    std::unordered_map<std::uint32_t, std::uint32_t> renumber;
    VertexLabeling result;
    result.labels.reserve(labels.size());
    for (const std::uint32_t label : labels)
        result.labels.push_back(renumber.try_emplace(label, std::uint32_t(renumber.size())).first->second);
    result.count = std::uint32_t(renumber.size());
    return result;
}

bool labelsAreConnected(const VertexGraph& graph, const VertexLabeling& labeling)
{
    // Components of the graph restricted to edges inside one label: one per label.
    std::vector<char> seen(graph.vertexCount(), 0);
    std::vector<char> labelSeen(labeling.count, 0);
    std::vector<std::uint32_t> queue;
    for (std::size_t start = 0; start < graph.vertexCount(); ++start) {
        if (seen[start])
            continue;
        const std::uint32_t label = labeling.labels[start];
        if (labelSeen[label])
            return false; // a second piece of the same label
        labelSeen[label] = 1;
        seen[start] = 1;
        queue.assign(1, std::uint32_t(start));
        for (std::size_t head = 0; head < queue.size(); ++head) {
            for (const std::uint32_t n : graph.neighborsOf(queue[head])) {
                if (!seen[n] && labeling.labels[n] == label) {
                    seen[n] = 1;
                    queue.push_back(n);
                }
            }
        }
    }
    return true;
}

} // namespace trimlab
