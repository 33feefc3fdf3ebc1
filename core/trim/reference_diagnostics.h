#pragma once
/// \file
/// Per-pixel numbers that say how close the CPU reference's decision for a pixel was to
/// flipping, so GPU-vs-reference tests can define ambiguous pixels honestly (a float
/// rasteriser may decide those either way) instead of using blanket tolerances.

#include "core/trim/clip_plane.h"
#include "core/trim/ray_hit.h"
#include "core/trim/trim_walk.h"
#include "core/view/camera.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace trimlab {

/// width×height planes, row 0 at the top.
/// - `edgeDistancePx`: distance in pixels from the pixel centre to the nearest edge of the
///   shown triangle's screen projection (after clipping it at the near plane, whose cut is
///   an edge the GPU rasterises too); +inf for empty pixels. Small: coverage may flip.
/// - `depthMargin`: see pixelDepthMargin; small: the depth order that decided may flip.
/// - `hitCount`: number of hits with zNear <= t <= zFar (the pixel's fragment count).
struct ReferenceDiagnostics {
    int width = 0;
    int height = 0;
    std::vector<float> edgeDistancePx;
    std::vector<float> depthMargin;
    std::vector<std::int32_t> hitCount;

    ReferenceDiagnostics() = default;
    ReferenceDiagnostics(int w, int h)
        : width(w),
          height(h),
          edgeDistancePx(size(), std::numeric_limits<float>::infinity()),
          depthMargin(size(), std::numeric_limits<float>::infinity()),
          hitCount(size(), 0)
    {
    }
    [[nodiscard]] std::size_t index(int x, int y) const { return std::size_t(y) * std::size_t(width) + std::size_t(x); }

private:
    [[nodiscard]] std::size_t size() const { return std::size_t(width) * std::size_t(height); }
};

/// How close the depth order that decided this pixel was to flipping.
/// Take the depths of all hits together with the markers tStart and tEnd (and the
/// span's runner-up plane bounds, see KeptSpan), sorted. The decision depends on the
/// order of the window from the last depth before tStart up to the first depth after the
/// deciding one (tStart for a cap, the shown hit, or tEnd when nothing is shown).
/// Returns the smallest |a − b| / max(a, b) over consecutive depths of that window: 0 for
/// exact ties (coincident surfaces, a hit exactly on the clip plane), +inf for an empty
/// span or a window of one depth. `scratch` is reused storage.
[[nodiscard]] double pixelDepthMargin(std::span<const RayHit> sortedHits, const KeptSpan& span, const TrimWalk& walk,
                                      std::vector<double>& scratch);

/// Distance in pixels from the centre of pixel (x, y) of a width×height image to the
/// nearest edge of world triangle `corners` projected with `camera` (the projection of
/// pixelRay), after clipping the triangle at the near plane. +inf if nothing is left.
[[nodiscard]] double edgeDistancePixels(const Camera& camera, int width, int height, int x, int y,
                                        const std::array<glm::dvec3, 3>& corners);

} // namespace trimlab
