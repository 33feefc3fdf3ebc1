#pragma once
/// \file
/// Medial balls of a closed mesh's vertices by ball shrinking (Ma, Bae & Choi 2012): the
/// ball touching the surface at vertex p from inside (centre p + r·m, m the inward
/// normal) is shrunk until no other vertex lies inside it. Where a ball holds a vertex q,
/// the next ball is the one through p and q, r = |q − p|² / (2 m·(q − p)), which is
/// smaller; a ball that holds no vertex touches the surface at p and at one or more other
/// places, so its centre lies on the (sampled) medial axis — CGAL's mean-curvature-flow
/// skeleton gets the same points from the Voronoi poles of the vertices.
///
/// Why here: the contraction's medial attraction needs one medial point per
/// vertex. The inward chord's midpoint (skeleton_refinement.h) depends on where a single
/// ray lands: at the cap of a limb the ray runs along the axis and its midpoint lies half
/// a limb back, on a bent limb the far wall is hit obliquely. The ball starts as the
/// chord's ball (through the far crossing) and only shrinks, so at a cap it settles at
/// the cap's own radius, on a tube at the tube's radius, wherever the ray landed.

#include "core/mesh/triangle_mesh.h"
#include "core/skeleton/point_in_mesh.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace trimlab {

/// At most this many shrinking steps per vertex; the radius falls every step, measured
/// 3–6 steps typical (none reached the cap on the shared meshes).
inline constexpr int kMaxBallShrinkSteps = 48;

/// A vertex inside the ball that the centre sees within this angle of p does not shrink it
/// (Ma et al.'s denoising by separation angle). Such a vertex lies on p's own sheet: where
/// p's normal is tilted against the true surface's (a faceted cap, the irregular
/// triangles of an iso-surface mesh), the tangent ball pokes through the surface beside
/// p, and shrinking on its neighbours would end at about edge / (2·sin tilt) — half the
/// tube's radius on the test star's 20°-noisy normals. A second contact across a tube
/// is seen 180° away, at a junction or a cap's rim 60° or more.
inline constexpr double kMinSeparationDegrees = 30.0;

/// The medial balls of one mesh's vertices, each computed on demand (the branch recovery
/// needs only the vertices near the parts no branch reaches). Holds a kd-tree over the
/// vertices; centre() is const and safe to call concurrently.
class ShrinkingBalls {
public:
    /// `midpoints` holds one entry per vertex (inwardChordMidpoints: the starting balls);
    /// `inside` is built from `mesh`; both must outlive this object. Throws
    /// std::invalid_argument when `midpoints` has another size.
    ShrinkingBalls(const TriangleMesh& mesh, const std::vector<std::optional<glm::dvec3>>& midpoints,
                   const PointInMesh& inside);
    ~ShrinkingBalls();
    ShrinkingBalls(const ShrinkingBalls&) = delete;
    ShrinkingBalls& operator=(const ShrinkingBalls&) = delete;

    /// The centre of vertex v's medial ball, or none where the vertex has no midpoint (no
    /// normal, or its inward ray found no surface) or where the centre is not inside (a
    /// vertex-sampled ball can slip through a large triangle; such a point would pull the
    /// skeleton out of the solid).
    [[nodiscard]] std::optional<glm::dvec3> centre(std::size_t v) const;

private:
    struct Tree;
    const TriangleMesh& m_mesh;
    const std::vector<std::optional<glm::dvec3>>& m_midpoints;
    const PointInMesh& m_inside;
    std::unique_ptr<Tree> m_tree;
};

/// Every vertex's ShrinkingBalls::centre, parallel over vertices.
[[nodiscard]] std::vector<std::optional<glm::dvec3>>
shrinkingBallCentres(const TriangleMesh& mesh, const std::vector<std::optional<glm::dvec3>>& midpoints,
                     const PointInMesh& inside);

} // namespace trimlab
