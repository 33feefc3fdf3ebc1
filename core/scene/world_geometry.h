#pragma once
/// \file
/// World-space geometry of a scene object in double precision: the single place where
/// object vertices go through SceneObject::modelMatrix, so the BVH, the shading and the
/// diagnostics of the CPU reference all see bitwise identical world positions.

#include "core/scene/scene.h"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace trimlab {

/// #V world positions: modelMatrix · (p, 1), divided by w when w != 1 (a projective
/// model matrix). Non-finite inputs stay non-finite (callers skip those triangles).
[[nodiscard]] std::vector<glm::dvec3> worldPositions(const SceneObject& object);

/// "" when the object's model matrix and every world position it gives are finite in
/// single precision (what the GPU, the exports and every file format hold), else what
/// overflows, for a message that names the object: "its model matrix entry [3][0] is
/// 1e+39, beyond single precision (±3.4e+38)" or "it places a vertex at x = -5e+38,
/// beyond single precision (±3.4e+38)". The world box is checked at the corners of the
/// mesh's box (the model matrix is affine), so this costs one pass over the vertices.
[[nodiscard]] std::string placementProblem(const SceneObject& object);

/// #V world-space vertex normals: the angle-weighted vertexNormals() of the object mesh
/// times the inverse-transpose of modelMatrix's upper 3×3, NOT renormalised (as a vertex
/// shader passes them on; normalise after interpolation). Zero for isolated vertices and
/// for a singular model matrix.
[[nodiscard]] std::vector<glm::dvec3> worldNormals(const SceneObject& object);

} // namespace trimlab
