#pragma once
/// \file
/// Inside/outside queries against a closed mesh, for the refinement's check that a
/// recentred skeleton node stays inside the model (Berenguer & Moreno III.C) and for
/// tests that check where skeleton nodes lie.

#include "core/mesh/triangle_mesh.h"
#include "core/trim/triangle_bvh.h"

#include <glm/vec3.hpp>

#include <limits>
#include <optional>

namespace trimlab {

/// Ray-parity point-in-mesh test over a BVH (trim/triangle_bvh.h, whose watertight
/// triangle test hits exactly one triangle where a ray passes through a shared edge or
/// vertex, so counts are exact). Orientation-free, so faces need not be consistently
/// oriented. Immutable after construction; contains() is safe to call concurrently.
class PointInMesh {
public:
    /// Builds the BVH over `mesh` (expected closed; for an open mesh the answer is the
    /// parity of crossings, which has no inside/outside meaning). O(F log F).
    explicit PointInMesh(const TriangleMesh& mesh);

    /// True when `p` is inside: at least two of three rays in fixed, generic directions
    /// cross the surface an odd number of times (one ray suffices for a closed mesh; the
    /// vote guards against a ray that grazes a surface tangentially). Points on the
    /// surface (a ray crosses it within 1e-9 of the model's size, e.g. at a mesh vertex
    /// or on an edge) are outside: the refinement must not move a node whose region is
    /// a single vertex onto that vertex. Non-finite points are outside. O(log F) typical.
    [[nodiscard]] bool contains(const glm::dvec3& p) const;

    /// The distance along the unit `direction` from `origin` to the nearest surface crossing
    /// farther than `tMin` and not farther than `tMax`; none when there is none in that
    /// range (with tMax infinite: when the ray leaves the mesh's bounds without one). A
    /// finite tMax makes the query cheaper where the caller only wants crossings nearer
    /// than one it already has (boxes beyond it are never opened).
    [[nodiscard]] std::optional<double> nearestCrossing(const glm::dvec3& origin, const glm::dvec3& direction,
                                                        double tMin,
                                                        double tMax = std::numeric_limits<double>::infinity()) const;

    /// True when the closed segment [p, q] lies inside: both ends are (contains) and the
    /// ray from p towards q crosses no surface before q. One point query per end and one
    /// ray, exact where contains() is.
    [[nodiscard]] bool segmentInside(const glm::dvec3& p, const glm::dvec3& q) const;

    /// The radius of the mesh's bounding sphere (a length scale for offsets).
    [[nodiscard]] double radius() const { return m_bounds.radius(); }

private:
    TriangleBvh m_bvh;
    Bounds m_bounds;
};

} // namespace trimlab
