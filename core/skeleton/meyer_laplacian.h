#pragma once
/// \file
/// The discrete Laplace–Beltrami operator of Meyer, Desbrun, Schröder and Barr (2003), the
/// Δ of the bone-heat equation (Berenguer & Moreno III.E, eq. 13–14):
///
///     (Δf)_i = 1/A_i · Σ_{j ∈ N(i)} ½ (cot α_ij + cot β_ij) (f_j − f_i)
///
/// with A_i the mixed Voronoi area of vertex i. It is returned split into the symmetric
/// cotangent stiffness L (L_ij = −w_ij, L_ii = Σ_j w_ij, w_ij = ½(cot α_ij + cot β_ij)),
/// which is positive semi-definite, and the diagonal of areas, so that −Δ = A⁻¹L and a
/// system −Δw + Hw = Hp becomes the symmetric (L + A·H) w = A·H·p (bone_heat_weights.h).

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

/// One undirected edge i < j of the stiffness matrix with its weight w_ij (may be
/// negative next to obtuse angles; the matrix stays positive semi-definite).
struct LaplacianEdge {
    std::uint32_t i = 0;
    std::uint32_t j = 0;
    double weight = 0.0;
};

/// The operator of one mesh. Shapes: #V = positions.size().
struct MeyerLaplacian {
    std::vector<LaplacianEdge> edges; ///< unique, sorted by (i, j), i < j
    std::vector<double> diagonal;     ///< #V: L_ii = Σ_j w_ij
    std::vector<double> area;         ///< #V mixed Voronoi areas A_i (squared length units), ≥ 0
    std::size_t skippedTriangles = 0; ///< zero-area, repeated-index or non-finite triangles left out
    std::size_t scaledTriangles = 0;  ///< near-degenerate triangles whose cotangents were scaled down
};

/// Largest |cot| a triangle may contribute (an angle of about 6·10⁻⁴ degrees). A triangle
/// with a larger cotangent has all three scaled by the same factor (see meyerLaplacian).
inline constexpr double kMaxCotangent = 1.0e5;

/// Builds the operator. Per triangle (a, b, c):
/// - cotangents are dot/|cross| of the edge vectors at each corner. A triangle whose
///   |cross| is 0 (zero area), whose corners repeat an index or which has a non-finite
///   coordinate contributes nothing (counted in skippedTriangles). The three cotangents of
///   a sliver are not clamped one by one: for a triangle the quadratic form
///   Σ cot θ_k (f_i − f_j)² is semi-definite only while cot a·cot b + cot b·cot c +
///   cot c·cot a ≥ 0, which holds (= 1) for the true angles but breaks when one of them is
///   clamped alone. When max |cot| > kMaxCotangent all three are multiplied by
///   kMaxCotangent / max |cot| instead, which keeps the form semi-definite and bounds the
///   entries (no infinity, no NaN).
/// - areas are Meyer's mixed Voronoi areas: for a non-obtuse triangle each corner P gets
///   (|PR|² cot Q + |PQ|² cot R) / 8; for an obtuse one the obtuse corner gets half the
///   triangle's area and the other two a quarter each (the Voronoi region would leave
///   the triangle). They sum to the surface area.
/// Triangle indices must be < positions.size() (checked; a bad index throws
/// std::out_of_range naming the triangle).
[[nodiscard]] MeyerLaplacian meyerLaplacian(std::span<const glm::dvec3> positions,
                                            std::span<const glm::uvec3> triangles);

} // namespace trimlab
