#pragma once
/// \file
/// Deformation gradients of triangles and their rotation angles (thesis 2.2.1,
/// eq. 2.1–2.2, after Sumner & Popović 2004): the affine map of a triangle between a
/// reference pose and a deformed pose, made 3D by a fourth vertex along the normal, and
/// the angle of its rotational part from the polar decomposition X = R·S.

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <optional>
#include <span>
#include <vector>

namespace trimlab {

/// The triangle's corners v1, v2, v3 in one pose.
using TriangleCorners = std::array<glm::dvec3, 3>;

/// The fourth vertex v4 = v1 + (v2−v1)×(v3−v1) / sqrt(|(v2−v1)×(v3−v1)|): along the
/// normal, with a length proportional to the edge lengths, so that scaling the triangle
/// scales v4−v1 alike. Equals v1 for a degenerate triangle.
[[nodiscard]] glm::dvec3 fourthVertex(const TriangleCorners& corners);

/// X_f with X_f·[v2−v1, v3−v1, v4−v1]_reference = [v2−v1, v3−v1, v4−v1]_deformed, i.e.
/// X_f = E_deformed · E_reference⁻¹ (column-major glm matrix). This maps the reference to
/// the deformed pose; eq. 2.2 writes the inverse map, whose rotation has the same angle.
/// nullopt when either triangle is degenerate: zero area, or an area (|cross product|) below 1e-10 of its
/// squared longest edge (a sliver whose frame cannot be inverted reliably), or
/// non-finite corners.
[[nodiscard]] std::optional<glm::dmat3> deformationGradient(const TriangleCorners& reference,
                                                            const TriangleCorners& deformed);

/// The rotation R of the polar decomposition X = R·S (R orthogonal with det +1, S
/// symmetric), from the singular value decomposition X = UΣVᵀ: R = UVᵀ. When det(UVᵀ) < 0
/// (X contains a reflection) the sign of U's column of the smallest singular value is
/// flipped, which gives the closest proper rotation instead of a reflection. X must be
/// finite; a singular X still yields a rotation.
[[nodiscard]] glm::dmat3 polarRotation(const glm::dmat3& x);

/// The rotation angle θ ∈ [0, π] of the rotation matrix R. The thesis writes
/// θ = arccos((tr R − 1)/2); this uses atan2(|axial vector of R−Rᵀ|/2, (tr R − 1)/2),
/// the same angle without arccos's loss of precision near 0 and π.
[[nodiscard]] double rotationAngle(const glm::dmat3& rotation);

/// θ_f for every triangle between `reference` and `deformed` positions (#V each, same
/// indices): rotationAngle(polarRotation(X_f)), in radians. Faces that are degenerate in
/// either pose get NaN.
[[nodiscard]] std::vector<double> faceRotationAngles(std::span<const glm::vec3> reference,
                                                     std::span<const glm::vec3> deformed,
                                                     std::span<const glm::uvec3> triangles);

/// How the per-vertex angle θ_v combines the angles of the faces around a vertex.
enum class VertexAveraging {
    Uniform,      ///< the number average of θ_f over the surrounding faces (thesis 2.2.1)
    AreaWeighted, ///< weighted by each face's area in the reference pose
};

/// θ_v for #V = `vertexCount` vertices from the face angles (NaN faces are skipped). A
/// vertex without a usable face gets 0 (it is treated as not rotating). `reference`
/// gives the face areas for AreaWeighted.
[[nodiscard]] std::vector<double> vertexRotationAngles(std::span<const double> faceAngles,
                                                       std::span<const glm::uvec3> triangles,
                                                       std::span<const glm::vec3> reference, std::size_t vertexCount,
                                                       VertexAveraging averaging);

} // namespace trimlab
