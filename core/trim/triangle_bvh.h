#pragma once
/// \file
/// A bounding volume hierarchy over every world-space triangle of a Scene, in double
/// precision, answering "all hits of this ray in [tMin, tMax]" — the CPU reference needs
/// every surface crossing of a pixel ray, not just the closest one.

#include "core/scene/scene.h"
#include "core/trim/ray_hit.h"
#include "core/view/camera.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace trimlab {

/// One triangle as stored in the BVH: world-space corners and where it came from.
struct BvhTriangle {
    glm::dvec3 a, b, c;
    int objectId = -1;    ///< index into Scene::objects
    int primitiveId = -1; ///< triangle index within that object's mesh
};

/// One node of the flattened tree (depth-first order). An inner node's left child is the
/// next node; `index` is its right child. A leaf (`count` > 0) holds the triangles
/// [index, index + count) of the reordered triangle array.
struct BvhNode {
    glm::dvec3 lower{0.0};
    glm::dvec3 upper{0.0};
    std::uint32_t index = 0;
    std::uint32_t count = 0;
};

/// Immutable after construction; intersectAll and intersectNearest are safe to call from
/// many threads.
class TriangleBvh {
public:
    /// Builds over all triangles of all objects (binned SAH, 16 bins on each axis).
    /// Vertices go through worldPositions() (scene/world_geometry.h). Skipped, because the
    /// watertight test can never hit them: triangles with a repeated vertex index, with two
    /// identical world corners, or with a non-finite world coordinate. Zero-area triangles
    /// with distinct corners (collinear) are kept: the watertight test may hit their
    /// rounded projection, and dropping them could open a crack between their neighbours.
    explicit TriangleBvh(const Scene& scene);

    /// Appends to `hits` EVERY hit with tMin <= t <= tMax, in no particular order (sort
    /// with walkOrder). Triangles are tested with intersectTriangle (trim/ray_triangle.h),
    /// so rays through shared edges and vertices hit exactly one triangle per sheet.
    /// Boxes are tested conservatively (padded by 1e-10 of the ray's distance scale) so
    /// box rounding never loses a hit that the triangle test would report.
    void intersectAll(const PixelRay& ray, double tMin, double tMax, std::vector<RayHit>& hits) const;

    /// The hit of smallest t in [tMin, tMax], or nullopt: the t that the smallest of
    /// intersectAll's hits has (of hits at equal t, any one). Visits the nearer child first
    /// and skips every box beyond the best hit so far (with the same conservative padding),
    /// so a ray from inside a closed mesh tests the triangles around its first crossing
    /// instead of every crossing through the mesh — what the skeleton's chords ask.
    [[nodiscard]] std::optional<RayHit> intersectNearest(const PixelRay& ray, double tMin, double tMax) const;

    [[nodiscard]] std::size_t triangleCount() const { return m_triangles.size(); }
    [[nodiscard]] std::size_t nodeCount() const { return m_nodes.size(); }
    [[nodiscard]] int depth() const { return m_depth; }
    [[nodiscard]] const std::vector<BvhTriangle>& triangles() const { return m_triangles; }
    [[nodiscard]] const std::vector<BvhNode>& nodes() const { return m_nodes; }

private:
    void build(std::vector<BvhTriangle> triangles);

    std::vector<BvhTriangle> m_triangles; // leaf order
    std::vector<BvhNode> m_nodes;
    int m_depth = 0;
    glm::dvec3 m_center{0.0};
    double m_radius = 0.0;
};

/// Collects the world triangles of `scene` exactly as TriangleBvh stores them (same
/// skipping rules), in object/primitive order. Used by brute-force tests.
[[nodiscard]] std::vector<BvhTriangle> collectWorldTriangles(const Scene& scene);

} // namespace trimlab
