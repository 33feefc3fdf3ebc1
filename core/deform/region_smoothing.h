#pragma once
/// \file
/// Iterative Laplacian smoothing restricted to a stroke's region (thesis 8.2: it removes
/// the lumps and creases an extreme stretch leaves on coarse meshes).

#include "core/deform/region_patch.h"
#include "core/deform/stroke.h"

#include <glm/vec3.hpp>

#include <span>

namespace trimlab::deform {

/// `iterations` Jacobi steps p_r ← p_r + λ_r·L(p)_r for the region vertices r of `patch`,
/// with L(p)_r = Σ_j w_rj (p_j − p_r) over the one-ring and Σ_j w_rj = 1:
/// - Uniform: w_rj = 1/deg(r) (the umbrella operator).
/// - Cotangent: w_rj ∝ max(0, (cot α_rj + cot β_rj)/2) from the current positions of each
///   iteration, normalised to sum 1. Clamping keeps each step a convex combination of
///   the vertex and its neighbours (negative weights across obtuse triangles can push a
///   vertex out of its ring and fold the mesh); normalising makes λ a fraction of the way
///   to the weighted ring average, so λ ∈ (0, 1] is stable for either weighting. On a
///   plane the unclamped cotangent Laplacian is exactly normal-directed (zero), so flat
///   parts do not slide. A vertex whose weights all clamp to 0 falls back to uniform.
/// Halo vertices (local ids >= regionSize()) are the fixed boundary: read, never written.
///
/// `positions`: patch.size() points (local ids), updated in place. `steps`: λ_r per
/// region vertex, in [0, 1]. Deterministic: fixed summation order, no threads.
void smoothRegion(const RegionPatch& patch, std::span<glm::dvec3> positions, std::span<const double> steps,
                  SmoothingWeights weights, int iterations);

} // namespace trimlab::deform
