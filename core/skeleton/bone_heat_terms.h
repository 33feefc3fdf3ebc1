#pragma once
/// \file
/// The heat sources of the bone-heat equation −Δwⁱ + H wⁱ = H pⁱ (Berenguer & Moreno
/// III.E, eq. 14, after Baran & Popović 2007): for every vertex j its nearest bone(s) by
/// point–segment distance d(j), whether the shortest segment to each of them stays inside
/// the mesh, the diagonal H_jj and the source values p_jⁱ.
///
/// Rules (eq. 14 and the text after it):
/// - the bones are grouped by distance from j, equidistant ones (within a relative
///   tolerance: at a joint several bones share the closest point, the joint) together;
/// - a bone of a group is visible when its shortest segment from j lies inside the mesh
///   (SegmentVisibility). The nearest bones of j are the nearest group with a visible
///   bone, as Pinocchio heats a vertex from its nearest *visible* bone: the side of a
///   body that an arm hangs beside is nearer to the arm's bone, across the gap, but does
///   not see it, and is heated by the spine it sees. With k visible bones in that group,
///   p_jⁱ = 1/k for each of them, 0 for every other bone, and H_jj = k·c / d(j)², d(j)
///   the group's distance;
/// - with no bone visible at all, H_jj = 0 and p_j = 0: the vertex gets its weights from
///   diffusion alone (bone_heat_weights.h); its nearest bones are then the nearest group.

#include "core/mesh/triangle_mesh.h"
#include "core/skeleton/skeleton.h"
#include "core/trim/ray_hit.h"
#include "core/trim/triangle_bvh.h"

#include "core/util/task_control.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

/// The point of segment [a, b] closest to p (a when a == b).
[[nodiscard]] glm::dvec3 closestPointOnSegment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b);

/// "Does the straight segment from a surface vertex to a point lie inside the mesh?",
/// answered with the exact ray–triangle test of the CPU reference renderer
/// (trim/triangle_bvh.h) against the mesh's own triangles. Immutable; thread-safe.
///
/// A segment p → q (p a mesh vertex, ray parameter t = 0 at p and 1 at q) is inside iff
/// the winding number is non-zero on all of it, for t ∈ [ε, 1 − ε] with ε =
/// kSegmentEpsilon. The winding number along the ray is counted from its crossings: 0
/// beyond the last one, changing by the facing of each (trim/ray_hit.h). On a closed
/// mesh without self-intersections this is "no crossing on the segment and inside";
/// on a self-intersecting one (TrimLab's subject, and common in real scans and animation
/// frames) crossing a sheet that lies inside the volume (w 1 → 2) keeps the segment
/// inside, as Baran & Popović's "contained in the volume" asks, whereas a crossing test
/// alone would call it blocked.
/// Why shrink by ε: the ray starts ON the surface, so the triangles around p are hit at
/// t = 0 up to rounding (about 1e-16); without the shrink every vertex would see its own
/// faces. A segment that leaves p outward (a bone poking out of the surface near p) has
/// w = 0 and is outside. A segment shorter than 1e-12 of the mesh size (p lies on the
/// bone) is inside. On an open mesh winding numbers are not integers and the answer is
/// only approximate.
class SegmentVisibility {
public:
    /// Builds the BVH over `mesh` (degenerate triangles are skipped, as in TriangleBvh).
    explicit SegmentVisibility(const TriangleMesh& mesh);

    /// `hits` is scratch space (one per thread) so the queries do not allocate.
    [[nodiscard]] bool inside(const glm::dvec3& from, const glm::dvec3& to, std::vector<RayHit>& hits) const;

private:
    TriangleBvh m_bvh;
    glm::dvec3 m_center{0.0};
    double m_radius = 0.0;
};

/// The relative shrink of a visibility segment at both ends (see SegmentVisibility).
inline constexpr double kSegmentEpsilon = 1.0e-6;

struct BoneHeatTermOptions {
    double heatConstant = 1.0;  ///< c of H_jj = c/d²; Pinocchio's 1 (the paper: c ≈ 0.22 mimics volume heat)
    double tieTolerance = 1e-6; ///< bones with d ≤ d_min·(1 + tieTolerance) are equidistant
    bool visibility = true;     ///< false: every nearest bone counts as visible (no ray tests)
    unsigned threads = 0;       ///< 0 = all cores
};

/// Per-vertex terms; #V = the mesh's vertex count. The nearest bones of vertex j are
/// nearestBones[nearestOffsets[j] .. nearestOffsets[j+1]) (at least one, ascending bone
/// index) with visible[] telling which of them are visible.
struct BoneHeatTerms {
    std::vector<double> heat;                  ///< #V: H_jj in 1/length², 0 when no bone is visible
    std::vector<double> distance;              ///< #V: d(j), floored at 1e-9 of the rig+mesh size
    std::vector<std::uint32_t> nearestOffsets; ///< #V + 1
    std::vector<int> nearestBones;
    std::vector<std::uint8_t> visible;
    std::size_t hiddenVertices = 0; ///< vertices whose H_jj is 0

    [[nodiscard]] std::span<const int> nearest(std::size_t vertex) const;
    /// k: the number of visible nearest bones of `vertex`.
    [[nodiscard]] std::size_t visibleCount(std::size_t vertex) const;
    /// p_jⁱ of eq. 14: 1/k when `bone` is one of the k visible nearest bones, else 0.
    [[nodiscard]] double source(std::size_t vertex, int bone) const;
};

/// Computes the terms for every vertex of `mesh` (O(#V·#bones) distances plus one ray
/// query per nearest bone, and more for a vertex whose nearest bones it does not see). Throws std::invalid_argument when the rig has no bones, a
/// bone names a joint outside rig.joints, a joint is not finite, c is not finite and
/// > 0, or the tie tolerance is negative or not finite; a vertex with a non-finite
/// position gets no visible bone. OperationCancelled when `control` asks to stop (stage
/// "visibility").
[[nodiscard]] BoneHeatTerms boneHeatTerms(const TriangleMesh& mesh, const SkeletonRig& rig,
                                          const BoneHeatTermOptions& options = {}, const TaskControl& control = {});

} // namespace trimlab
