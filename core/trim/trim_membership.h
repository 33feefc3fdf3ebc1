#pragma once
/// \file
/// Whether points of the shown frame's surface belong to its trim under the dynamic rules,
/// i.e. whether the space on their two sides classifies differently. The homogeneous
/// confluent rule (thesis 8.1.1) forbids deforming surface parts that were trimmed off;
/// the brush asks this before a stroke starts.

#include "core/trim/dynamic_reference_renderer.h"

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace trimlab {

/// For each surface point (world space) with its outward normal (need not be unit
/// length; a zero normal counts as on the trim): true when the point is on the trim of the
/// chain's shown frame. Decided exactly like a pixel of DynamicReferenceRenderer, along a
/// ray that starts just inside the point (offset `epsilon` against the normal) and leaves
/// through it: on the trim iff the first current-frame hit the dynamic walk meets there
/// changes the class. Multithreaded over points.
[[nodiscard]] std::vector<bool> pointsOnTrim(const DynamicReferenceRenderer& chain, std::span<const glm::dvec3> points,
                                             std::span<const glm::dvec3> normals, double epsilon);

} // namespace trimlab
