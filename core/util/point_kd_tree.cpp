#include "core/util/point_kd_tree.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace trimlab {

namespace {

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

bool isFinite(const glm::dvec3& p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

} // namespace

PointKdTree::PointKdTree(std::vector<glm::dvec3> points) : m_points(std::move(points))
{
    if (m_points.size() > std::numeric_limits<std::uint32_t>::max())
        throw std::length_error("PointKdTree: more points than a 32-bit index can name");
    m_order.reserve(m_points.size());
    for (std::size_t i = 0; i < m_points.size(); ++i)
        if (isFinite(m_points[i]))
            m_order.push_back({static_cast<std::uint32_t>(i), 0});
    build(0, m_order.size());
}

void PointKdTree::build(std::size_t begin, std::size_t end)
{
    // Iterative over the larger half would bound the stack; the depth is log2(n) ≤ 32
    // because every range halves, so plain recursion is safe.
    if (end - begin <= 1)
        return;
    glm::dvec3 lower(std::numeric_limits<double>::infinity());
    glm::dvec3 upper(-std::numeric_limits<double>::infinity());
    for (std::size_t i = begin; i < end; ++i) {
        lower = glm::min(lower, m_points[m_order[i].point]);
        upper = glm::max(upper, m_points[m_order[i].point]);
    }
    const glm::dvec3 extent = upper - lower;
    const std::uint8_t axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::size_t middle = (begin + end) / 2;
    std::nth_element(m_order.begin() + static_cast<std::ptrdiff_t>(begin),
                     m_order.begin() + static_cast<std::ptrdiff_t>(middle),
                     m_order.begin() + static_cast<std::ptrdiff_t>(end),
                     [&](const Node& a, const Node& b) { return m_points[a.point][axis] < m_points[b.point][axis]; });
    m_order[middle].axis = axis;
    build(begin, middle);
    build(middle + 1, end);
}

template <class Skip>
NearestPoint PointKdTree::bounded(const glm::dvec3& query, double belowSquared, const Skip& skip) const
{
    // The bound acts as a point already found at that distance, with no index: the search
    // only takes points strictly closer (a tie at the bound would lose to any real index).
    NearestPoint best;
    best.distanceSquared = belowSquared;
    if (isFinite(query))
        search(0, m_order.size(), query, skip, glm::dvec3(0.0), 0.0, best);
    if (best.index == kNone)
        best.distanceSquared = std::numeric_limits<double>::infinity();
    return best;
}

NearestPoint PointKdTree::nearest(const glm::dvec3& query, std::size_t excluded, double belowSquared) const
{
    return bounded(query, belowSquared,
                   [excluded](std::uint32_t point, const glm::dvec3&) { return point == excluded; });
}

NearestPoint PointKdTree::nearestAwayFrom(const glm::dvec3& query, double belowSquared, const glm::dvec3& around,
                                          double aroundSquared) const
{
    return bounded(query, belowSquared, [&](std::uint32_t, const glm::dvec3& p) {
        const glm::dvec3 d = p - around;
        return d.x * d.x + d.y * d.y + d.z * d.z < aroundSquared;
    });
}

template <class Skip>
void PointKdTree::search(std::size_t begin, std::size_t end, const glm::dvec3& query, const Skip& skip,
                         glm::dvec3 offsets, double boxDistanceSquared, NearestPoint& best) const
{
    if (begin >= end)
        return;
    const std::size_t middle = (begin + end) / 2;
    const Node& node = m_order[middle];
    const glm::dvec3& p = m_points[node.point];
    if (!skip(node.point, p)) {
        const glm::dvec3 d = p - query;
        const double distanceSquared = d.x * d.x + d.y * d.y + d.z * d.z;
        if (distanceSquared < best.distanceSquared ||
            (distanceSquared == best.distanceSquared && best.index != kNone && node.point < best.index))
            best = {node.point, distanceSquared};
    }
    if (end - begin == 1)
        return;
    // The near side first, so the far side is usually pruned. The far side is pruned by
    // the distance to its cell, not just to the splitting plane: `offsets` holds the
    // query's distance to the cell on each axis (Arya & Mount's incremental distance),
    // which matters for queries from the inside of a tube, whose nearest points are a
    // whole ring at almost the same distance.
    const double offset = query[node.axis] - p[node.axis];
    const bool queryBelow = offset < 0.0;
    if (queryBelow)
        search(begin, middle, query, skip, offsets, boxDistanceSquared, best);
    else
        search(middle + 1, end, query, skip, offsets, boxDistanceSquared, best);
    const double farDistanceSquared = boxDistanceSquared - offsets[node.axis] * offsets[node.axis] + offset * offset;
    if (farDistanceSquared <= best.distanceSquared) {
        offsets[node.axis] = offset;
        if (queryBelow)
            search(middle + 1, end, query, skip, offsets, farDistanceSquared, best);
        else
            search(begin, middle, query, skip, offsets, farDistanceSquared, best);
    }
}

} // namespace trimlab
