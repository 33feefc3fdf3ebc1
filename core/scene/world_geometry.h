#pragma once
/// \file
/// World-space geometry of a scene object in double precision: the single place where
/// object vertices go through SceneObject::modelMatrix, so the BVH, the shading and the
/// diagnostics of the CPU reference all see bitwise identical world positions.

#include "core/scene/scene.h"

#include <glm/vec3.hpp>

#include <vector>

namespace trimlab {

/// #V world positions: modelMatrix · (p, 1), divided by w when w != 1 (a projective
/// model matrix). Non-finite inputs stay non-finite (callers skip those triangles).
[[nodiscard]] std::vector<glm::dvec3> worldPositions(const SceneObject& object);

/// #V world-space vertex normals: the angle-weighted vertexNormals() of the object mesh
/// times the inverse-transpose of modelMatrix's upper 3×3, NOT renormalised (as a vertex
/// shader passes them on; normalise after interpolation). Zero for isolated vertices and
/// for a singular model matrix.
[[nodiscard]] std::vector<glm::dvec3> worldNormals(const SceneObject& object);

} // namespace trimlab
