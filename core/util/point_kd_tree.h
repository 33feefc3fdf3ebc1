#pragma once
/// \file
/// Nearest-neighbour queries over a fixed set of 3D points: a balanced kd-tree stored as
/// a permutation of the points (the median of each range is its node, split on the axis
/// of the range's largest extent), so it needs no node allocation and builds in
/// O(n log n). Used where a query repeats per mesh vertex (the shrinking balls of the
/// skeleton's medial points) and a brute-force scan would be quadratic.

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace trimlab {

/// A point of the tree and its squared distance to the query.
struct NearestPoint {
    std::size_t index = std::numeric_limits<std::size_t>::max(); ///< into the constructor's points; max: none
    double distanceSquared = std::numeric_limits<double>::infinity();
    [[nodiscard]] bool found() const { return index != std::numeric_limits<std::size_t>::max(); }
};

/// Immutable after construction; nearest() is safe to call concurrently.
class PointKdTree {
public:
    /// Builds over `points` (kept by copy). Non-finite points are left out: no query
    /// returns them.
    explicit PointKdTree(std::vector<glm::dvec3> points);

    /// The point nearest to `query` other than `excluded` (pass the query point's own
    /// index, or max() to exclude nothing) among those closer than √`belowSquared`, ties
    /// to the lower index. None (index max) when there is no such point. A finite bound
    /// prunes the search to the ball, which is most of the cost when the answer is "none".
    [[nodiscard]] NearestPoint nearest(const glm::dvec3& query,
                                       std::size_t excluded = std::numeric_limits<std::size_t>::max(),
                                       double belowSquared = std::numeric_limits<double>::infinity()) const;

    /// As nearest(query, max(), belowSquared), leaving out every point closer than
    /// √`aroundSquared` to `around` (the neighbourhood of a surface point whose own sheet
    /// is not an answer).
    [[nodiscard]] NearestPoint nearestAwayFrom(const glm::dvec3& query, double belowSquared, const glm::dvec3& around,
                                               double aroundSquared) const;

    /// The number of points queries can return (the finite ones).
    [[nodiscard]] std::size_t size() const { return m_order.size(); }
    /// Point `index` as given to the constructor.
    [[nodiscard]] const glm::dvec3& point(std::size_t index) const { return m_points.at(index); }

private:
    struct Node {
        std::uint32_t point = 0; ///< index into m_points
        std::uint8_t axis = 0;
    };
    void build(std::size_t begin, std::size_t end);
    template <class Skip>
    void search(std::size_t begin, std::size_t end, const glm::dvec3& query, const Skip& skip, glm::dvec3 offsets,
                double boxDistanceSquared, NearestPoint& best) const;
    template <class Skip>
    [[nodiscard]] NearestPoint bounded(const glm::dvec3& query, double belowSquared, const Skip& skip) const;

    std::vector<glm::dvec3> m_points;
    std::vector<Node> m_order; ///< the subtree of [begin, end) has its node at (begin + end) / 2
};

} // namespace trimlab
