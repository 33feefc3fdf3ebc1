#pragma once
/// \file
/// A NURBS surface (thesis 8.2: the designer deforms it by moving control points, which
/// may push the surface through itself, Fig. 8.13) and its exact evaluation: points,
/// first partial derivatives (rational quotient rule) and unit normals, robust at poles.
///
/// S(u, v) = Σ_i Σ_j N_i,p(u) N_j,q(v) w_ij P_ij / Σ_i Σ_j N_i,p(u) N_j,q(v) w_ij
///
/// Control net layout (row-major, one row per v index):
///   index(i, j) = j · countU + i,   0 <= i < countU (along u),  0 <= j < countV (along v)
/// so "row j" is the control polygon of an iso-v curve and "column i" that of an iso-u
/// curve. Knot vectors are clamped (nurbs_basis.h), so the four boundary curves of the
/// parameter rectangle are the boundary rows/columns of the net.
///
/// Closed directions: when `closedU` is set, column countU−1 repeats column 0 exactly
/// (same positions and weights), so S(u_begin, v) = S(u_end, v) and the surface closes
/// along a seam (as the exact rational circle does: 9 control points, the last equal to
/// the first). Likewise `closedV` for rows.
/// Poles: an open boundary whose control points all sit at the same position (weights
/// may differ) collapses to one point — the poles of a sphere, the cap centres of a
/// capped tube. The tessellation makes them one vertex with a triangle fan.
/// Control points tied this way (seam twins, the points of one pole) must move together:
/// use moveControlPoint / setControlWeight, which keep them tied.
///
/// Orientation: the normal is Su × Sv (normalised); the primitives in nurbs_primitives.h
/// are parameterised so that it points out of the solid.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace trimlab {

/// Most control points one surface may have (files declaring more are refused before
/// anything is allocated).
inline constexpr std::size_t kMaxNurbsControlPoints = 1'000'000;

/// A tensor-product NURBS surface. Plain data: every field may be edited directly, then
/// checked with findNurbsProblem / requireValidNurbs (evaluation assumes a valid
/// surface and does not re-check it per call).
struct NurbsSurface {
    std::string name;               ///< shown in the UI and written to files; may be empty
    int degreeU = 3;                ///< p, 1..kMaxNurbsDegree
    int degreeV = 3;                ///< q, 1..kMaxNurbsDegree
    int countU = 0;                 ///< control points per row (along u), >= degreeU+1
    int countV = 0;                 ///< control points per column (along v), >= degreeV+1
    std::vector<double> knotsU;     ///< countU+degreeU+1 knots, clamped, non-decreasing
    std::vector<double> knotsV;     ///< countV+degreeV+1 knots, clamped, non-decreasing
    std::vector<glm::dvec3> points; ///< countU·countV positions P_ij at index(i, j) (scene units)
    std::vector<double> weights;    ///< countU·countV weights w_ij > 0 at index(i, j)
    bool closedU = false;           ///< column countU−1 repeats column 0 (seam along u)
    bool closedV = false;           ///< row countV−1 repeats row 0 (seam along v)

    /// j·countU + i (no range check).
    [[nodiscard]] std::size_t index(int i, int j) const
    {
        return std::size_t(j) * std::size_t(countU) + std::size_t(i);
    }
    [[nodiscard]] std::size_t controlPointCount() const { return points.size(); }

    friend bool operator==(const NurbsSurface&, const NurbsSurface&) = default;
};

/// A problem found by findNurbsProblem. `where` is a path relative to the surface, in the
/// JSON file's field names ("knotsU[3]", "weights[17]", "points[4]", "countU", "closedV"),
/// `reason` one sentence saying what is wrong and what to do.
struct NurbsProblem {
    std::string where;
    std::string reason;
};

/// Checks everything evaluation and tessellation rely on: degrees in 1..kMaxNurbsDegree,
/// counts >= degree+1 with countU·countV <= kMaxNurbsControlPoints, array sizes, knot
/// vectors (findKnotVectorProblem), finite positions, finite weights > 0, and for a closed
/// direction that the last row/column repeats the first exactly. nullopt when valid.
[[nodiscard]] std::optional<NurbsProblem> findNurbsProblem(const NurbsSurface& surface);

/// Throws std::invalid_argument "<caller>: <where>: <reason>" when findNurbsProblem
/// reports a problem.
void requireValidNurbs(const NurbsSurface& surface, const std::string& caller);

/// The parameter domain [begin, end] of one direction (first and last knot).
struct ParameterRange {
    double begin = 0.0;
    double end = 1.0;
    [[nodiscard]] double length() const { return end - begin; }
};
[[nodiscard]] ParameterRange parameterRangeU(const NurbsSurface& surface);
[[nodiscard]] ParameterRange parameterRangeV(const NurbsSurface& surface);

/// A point of the surface with its first partial derivatives (scene units per parameter
/// unit). At a pole one of the derivatives is (numerically) zero.
struct NurbsSample {
    glm::dvec3 position{0.0};
    glm::dvec3 du{0.0}; ///< ∂S/∂u
    glm::dvec3 dv{0.0}; ///< ∂S/∂v
};

/// S(u, v) and its partial derivatives. Parameters outside the domain are clamped to it.
/// `surface` must be valid (requireValidNurbs); O((p+1)(q+1)) after two span searches.
[[nodiscard]] NurbsSample evaluateNurbs(const NurbsSurface& surface, double u, double v);
/// S(u, v) only.
[[nodiscard]] glm::dvec3 evaluateNurbsPoint(const NurbsSurface& surface, double u, double v);

/// The unit normal Su × Sv / |Su × Sv| at (u, v). Where that cross product vanishes
/// (poles, collapsed edges, cusps: |Su × Sv| <= 1e-10 · |Su|·|Sv| or a derivative below
/// 1e-10 of the net's size per parameter length), returns the limit towards the interior
/// of the domain, approximated by normals at parameters nudged inward by 1e-6, 1e-4 and
/// 1e-2 of the domain length in turn. Returns (0, 0, 0) — never NaN — only when the
/// surface has no normal anywhere near (u, v) (e.g. the whole net is one point).
[[nodiscard]] glm::dvec3 nurbsNormal(const NurbsSurface& surface, double u, double v);

/// The length below which ∂S/∂u or ∂S/∂v counts as vanished (a pole, a collapsed edge):
/// 1e-10 of the control net's bounding-box diagonal per parameter length of the longer
/// direction. 0 for an empty net.
[[nodiscard]] double nurbsDerivativeFloor(const NurbsSurface& surface);
/// normalize(du × dv), or nullopt where it is degenerate: a derivative not longer than
/// `derivativeFloor`, |du × dv| <= 1e-10·|du|·|dv|, or a non-finite length. The test
/// behind nurbsNormal and the tessellation's normals.
[[nodiscard]] std::optional<glm::dvec3> regularNurbsNormal(const glm::dvec3& du, const glm::dvec3& dv,
                                                           double derivativeFloor);

/// The four boundary sides of the parameter rectangle.
enum class NurbsSide { UBegin, UEnd, VBegin, VEnd };

/// True when `side` lies in an open direction and all control points of that boundary
/// column (UBegin: i = 0, UEnd: i = countU−1) or row (VBegin: j = 0, VEnd: j = countV−1)
/// have exactly the same position: the side is a single point of the surface.
[[nodiscard]] bool isPole(const NurbsSurface& surface, NurbsSide side);

/// The control point `index` and every control point tied to it (its seam twin in a
/// closed direction, all points of a pole it belongs to, transitively), sorted
/// ascending; `index` alone when nothing is tied. Index out of range: empty.
[[nodiscard]] std::vector<std::size_t> linkedControlPoints(const NurbsSurface& surface, std::size_t index);

/// Moves control point `index` and every point linked to it to `position`. Throws
/// std::out_of_range for a bad index and std::invalid_argument for a non-finite position.
void moveControlPoint(NurbsSurface& surface, std::size_t index, const glm::dvec3& position);
/// Sets the weight of `index` and of its seam twin (pole points keep their own weights,
/// which may differ). Throws std::out_of_range / std::invalid_argument (weight not
/// finite or <= 0).
void setControlWeight(NurbsSurface& surface, std::size_t index, double weight);

} // namespace trimlab
