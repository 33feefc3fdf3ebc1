#include "core/animation/segment_coloring.h"

#include "core/animation/label_adjacency.h"
#include "core/animation/vertex_areas.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace trimlab {

namespace {

// Colours labels one at a time, avoiding conflicts with labels already coloured nearby.
class ColorAssigner {
public:
    ColorAssigner(std::vector<std::vector<std::uint32_t>> adjacency, int rings)
        : m_adjacency(std::move(adjacency)), m_rings(rings), m_colors(m_adjacency.size())
    {
    }

    [[nodiscard]] bool colored(std::uint32_t label) const { return m_colors[label].has_value(); }
    void assign(std::uint32_t label, const WheelColor& color)
    {
        m_colors[label] = color;
        reserve(color);
    }
    // Keeps `color` out of fresh colours (nextColor with fresh = true).
    void reserve(const WheelColor& color)
    {
        const std::size_t key = usedKey(color);
        if (key >= m_used.size())
            m_used.resize(key + 1, 0);
        m_used[key] = 1;
    }

    // True when a coloured label within m_rings steps has a colour `bad(color, theirs)`.
    template <class Bad>
    [[nodiscard]] bool nearby(std::uint32_t label, const WheelColor& color, const Bad& bad) const
    {
        for (const std::uint32_t n : m_adjacency[label]) {
            if (m_colors[n] && bad(color, *m_colors[n]))
                return true;
            if (m_rings < 2)
                continue;
            for (const std::uint32_t m : m_adjacency[n])
                if (m != label && m_colors[m] && bad(color, *m_colors[m]))
                    return true;
        }
        return false;
    }

    [[nodiscard]] bool conflicts(std::uint32_t label, const WheelColor& color) const
    {
        return nearby(label, color, nearlySame);
    }

    // The next palette colour after the cursor that does not conflict (and, when
    // `fresh`, that no label has yet, if such a colour exists in the first rings).
    WheelColor nextColor(std::uint32_t label, bool fresh)
    {
        for (const bool requireFresh : {fresh, false}) {
            for (std::size_t size = 12; size <= 12 + 24 * 8; size += 24) {
                for (std::size_t step = 0; step < size; ++step) {
                    const std::size_t index = (m_cursor + step) % size;
                    const WheelColor color = paletteColor(index);
                    if (conflicts(label, color) || (requireFresh && isUsed(color)))
                        continue;
                    m_cursor = index + 1;
                    return color;
                }
            }
        }
        return paletteColor(m_cursor++); // unreachable for planar-like label graphs
    }

    [[nodiscard]] std::vector<WheelColor> colors() const
    {
        std::vector<WheelColor> result;
        for (const std::optional<WheelColor>& c : m_colors)
            result.push_back(c.value_or(paletteColor(0)));
        return result;
    }
    [[nodiscard]] const std::vector<std::uint32_t>& neighbors(std::uint32_t label) const { return m_adjacency[label]; }
    [[nodiscard]] std::size_t size() const { return m_colors.size(); }

private:
    // Palette and mixed colours lie on a 15° grid: (ring, grid position) identifies them.
    static std::size_t usedKey(const WheelColor& color)
    {
        return std::size_t(color.ring) * 24 + std::size_t(std::lround(color.hue / 15.0)) % 24;
    }
    [[nodiscard]] bool isUsed(const WheelColor& color) const
    {
        const std::size_t key = usedKey(color);
        return key < m_used.size() && m_used[key];
    }

    std::vector<std::vector<std::uint32_t>> m_adjacency;
    int m_rings;
    std::vector<std::optional<WheelColor>> m_colors;
    std::vector<char> m_used; // by usedKey
    std::size_t m_cursor = 0;
};

// Breadth-first order over the label graph from `root`, then from the remaining labels
// in `fallback` order (one walk per component). Calls visit(label) once per label.
template <class Visit>
void walkLabels(const ColorAssigner& assigner, std::uint32_t root, const std::vector<std::uint32_t>& fallback,
                const Visit& visit)
{
    std::vector<char> queued(assigner.size(), 0);
    std::vector<std::uint32_t> queue;
    auto walkFrom = [&](std::uint32_t start) {
        queue.assign(1, start);
        queued[start] = 1;
        for (std::size_t head = 0; head < queue.size(); ++head) {
            visit(queue[head]);
            for (const std::uint32_t n : assigner.neighbors(queue[head])) {
                if (!queued[n]) {
                    queued[n] = 1;
                    queue.push_back(n);
                }
            }
        }
    };
    walkFrom(root);
    for (const std::uint32_t label : fallback)
        if (!queued[label])
            walkFrom(label);
}

// Labels by decreasing value, ties by smaller label.
std::vector<std::uint32_t> byDecreasing(const std::vector<double>& value)
{
    std::vector<std::uint32_t> order(value.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = std::uint32_t(i);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return value[a] > value[b]; });
    return order;
}

} // namespace

std::vector<WheelColor> colorSegments(const VertexGraph& graph, const VertexLabeling& labeling,
                                      std::span<const double> areas, int rings)
{
    if (labeling.count == 0)
        return {};
    ColorAssigner assigner(labelAdjacency(graph, labeling), rings);
    const std::vector<std::uint32_t> order = byDecreasing(labelAreas(labeling.labels, labeling.count, areas));
    walkLabels(assigner, order.front(), order,
               [&](std::uint32_t label) { assigner.assign(label, assigner.nextColor(label, false)); });
    return assigner.colors();
}

namespace {

struct Overlap {
    std::uint32_t past;
    double area;
};

// For every future label its overlaps with past labels, by decreasing area (ties: the
// smaller past label).
std::vector<std::vector<Overlap>> overlaps(std::span<const double> areas, const VertexLabeling& past,
                                           const VertexLabeling& future)
{
    std::vector<std::pair<std::uint64_t, double>> pairs;
    pairs.reserve(areas.size());
    for (std::size_t v = 0; v < areas.size(); ++v)
        pairs.emplace_back((std::uint64_t(future.labels[v]) << 32) | past.labels[v], areas[v]);
    std::sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::vector<Overlap>> result(future.count);
    for (std::size_t i = 0; i < pairs.size();) {
        const std::uint64_t key = pairs[i].first;
        double sum = 0.0;
        for (; i < pairs.size() && pairs[i].first == key; ++i)
            sum += pairs[i].second;
        result[key >> 32].push_back({std::uint32_t(key), sum});
    }
    for (std::vector<Overlap>& list : result)
        std::stable_sort(list.begin(), list.end(), [](const Overlap& a, const Overlap& b) { return a.area > b.area; });
    return result;
}

// The future label that covers most of each past label (ties: the smaller future label).
std::vector<std::uint32_t> owners(const std::vector<std::vector<Overlap>>& overlap, std::size_t pastCount)
{
    std::vector<std::uint32_t> owner(pastCount, UINT32_MAX);
    std::vector<double> best(pastCount, -1.0);
    for (std::uint32_t f = 0; f < overlap.size(); ++f) {
        for (const Overlap& o : overlap[f]) {
            if (o.area > best[o.past]) {
                best[o.past] = o.area;
                owner[o.past] = f;
            }
        }
    }
    return owner;
}

WheelColor chooseInherited(ColorAssigner& assigner, std::uint32_t f, const std::vector<Overlap>& list,
                           const std::vector<std::uint32_t>& owner, std::span<const WheelColor> pastColors)
{
    for (const Overlap& o : list) {
        if (owner[o.past] == f && !assigner.conflicts(f, pastColors[o.past]))
            return pastColors[o.past];
    }
    if (list.size() >= 2) {
        const std::optional<WheelColor> mix = mixColors(pastColors[list[0].past], pastColors[list[1].past]);
        if (mix && !assigner.conflicts(f, *mix) && !assigner.nearby(f, *mix, complementary))
            return *mix;
    }
    return assigner.nextColor(f, true);
}

} // namespace

std::vector<WheelColor> propagateColors(const VertexGraph& graph, std::span<const double> areas,
                                        const VertexLabeling& past, std::span<const WheelColor> pastColors,
                                        const VertexLabeling& future)
{
    if (future.count == 0)
        return {};
    const std::vector<std::vector<Overlap>> overlap = overlaps(areas, past, future);
    const std::vector<std::uint32_t> owner = owners(overlap, past.count);
    std::vector<double> largest(future.count, 0.0);
    for (std::size_t f = 0; f < overlap.size(); ++f)
        largest[f] = overlap[f].empty() ? 0.0 : overlap[f].front().area;
    const std::vector<std::uint32_t> order = byDecreasing(largest);
    ColorAssigner assigner(labelAdjacency(graph, future), 1);
    for (const WheelColor& color : pastColors)
        assigner.reserve(color); // a fresh colour must not look like an inherited one
    walkLabels(assigner, order.front(), order, [&](std::uint32_t f) {
        assigner.assign(f, chooseInherited(assigner, f, overlap[f], owner, pastColors));
    });
    return assigner.colors();
}

std::vector<std::vector<WheelColor>> colorSequence(const VertexGraph& graph, std::span<const double> areas,
                                                   std::span<const VertexLabeling> sequence)
{
    std::vector<std::vector<WheelColor>> colors;
    for (std::size_t i = 0; i < sequence.size(); ++i) {
        colors.push_back(i == 0 ? colorSegments(graph, sequence[0], areas)
                                : propagateColors(graph, areas, sequence[i - 1], colors.back(), sequence[i]));
    }
    return colors;
}

std::vector<glm::vec3> colorsRgb(std::span<const WheelColor> colors)
{
    std::vector<glm::vec3> rgb;
    rgb.reserve(colors.size());
    for (const WheelColor& c : colors)
        rgb.push_back(c.rgb());
    return rgb;
}

std::vector<glm::vec3> vertexColors(const VertexLabeling& labeling, std::span<const WheelColor> colors)
{
    std::vector<glm::vec3> rgb;
    rgb.reserve(labeling.labels.size());
    for (const std::uint32_t label : labeling.labels)
        rgb.push_back(colors[label].rgb());
    return rgb;
}

} // namespace trimlab
