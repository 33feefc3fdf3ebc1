#pragma once
/// \file
/// Triangulation of the polygonal faces of OBJ, OFF and PLY files: ear clipping in the
/// polygon's best-fit plane, so that non-convex faces are split correctly.

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

/// Polygons as read from a file, before triangulation: polygon p has the vertex indices
/// `corners[starts[p] .. starts[p + 1])`. `starts` always holds #P + 1 entries.
struct PolygonSoup {
    std::vector<std::uint32_t> corners;
    std::vector<std::size_t> starts{0};

    [[nodiscard]] std::size_t polygonCount() const { return starts.size() - 1; }
    [[nodiscard]] std::span<const std::uint32_t> polygon(std::size_t p) const
    {
        return std::span<const std::uint32_t>(corners).subspan(starts[p], starts[p + 1] - starts[p]);
    }
    /// Ends the polygon made of the corners appended since the previous call.
    void closePolygon() { starts.push_back(corners.size()); }
    /// Σ(n − 2) over the polygons: the triangle count after triangulation.
    [[nodiscard]] std::size_t triangleCount() const { return corners.size() - 2 * polygonCount(); }
};

/// Polygons with more corners than this are fanned instead of ear clipped (ear clipping
/// is quadratic or worse in the corner count).
inline constexpr std::size_t kMaxEarClippingCorners = 1024;

/// Appends the n − 2 triangles of `polygon` (n ≥ 3 indices into `positions`, all in range)
/// to `out`, each oriented like the polygon (counter-clockwise about its Newell normal).
/// - triangles are emitted as is; quads are split along the diagonal that keeps both
///   halves facing along the normal (0–2 when both do);
/// - larger polygons are projected onto the plane of their Newell normal and ear clipped,
///   which handles non-convex polygons;
/// - degenerate polygons (zero Newell normal, non-finite positions), polygons where no ear
///   can be found (self-intersecting) and polygons above kMaxEarClippingCorners fall back
///   to a fan from the first corner.
/// Polygons with fewer than 3 corners append nothing.
void triangulatePolygon(std::span<const glm::vec3> positions, std::span<const std::uint32_t> polygon,
                        std::vector<glm::uvec3>& out);

/// Triangulates every polygon of `soup` (indices in range, ≥ 3 corners each) in order.
[[nodiscard]] std::vector<glm::uvec3> triangulatePolygons(std::span<const glm::vec3> positions,
                                                          const PolygonSoup& soup);

} // namespace trimlab
