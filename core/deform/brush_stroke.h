#pragma once
/// \file
/// Applying a Stroke to a mesh, interactively (BrushStroke, one per mouse drag) or at
/// once (applyStroke, for replays). Geodesic distances are computed on the local region
/// around the anchor only (never the whole mesh), so a drag update stays interactive on
/// meshes of 100k vertices.

#include "core/deform/brush_topology.h"
#include "core/deform/region_patch.h"
#include "core/deform/stroke.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace trimlab::deform {

/// The vertices a stroke may move and how strongly: vertices with distance d < radius
/// from the anchor, with their falloff weight f(d/r) (before the angle term). d is the
/// smaller of the geodesic distances on the current surface and on the rest surface
/// (BrushTopology::restPositions(), from the anchor's barycentric point there), so a
/// stroke inside a stretched dent grabs at least the patch it would have grabbed before
/// the dent.
struct InfluenceRegion {
    std::vector<std::uint32_t> vertices;  ///< sorted ascending
    std::vector<double> geodesicDistance; ///< per entry of `vertices`
    std::vector<double> falloff;          ///< per entry, in [0, 1], non-increasing in distance
};

/// One drag in progress. Built when the mouse button goes down (computes the anchor, the
/// local geodesics, the falloff and the angle attenuation once); each update(drag)
/// recomputes the region's positions from the positions at the start of the drag, so the
/// result depends only on the total drag, not on the mouse path.
///
/// The warp moves region vertex v by strength·drag·f(d_v/r)·a_v, with the falloff f of
/// falloff.h and the angle term a_v of angle_attenuation.h (vertex normals and the
/// anchor's normal taken at drag start). Then settings.smoothingIterations Jacobi steps
/// of Laplacian smoothing (region_smoothing.h) with the step λ·f(d_v/r) at v: scaling λ
/// by the falloff fades the smoothing out towards the rim, so no ring-shaped crease
/// appears where the smoothed region meets the untouched surface, while the stretched
/// middle gets the full λ. A zero drag therefore still smooths around the anchor when
/// iterations > 0. The region is empty (nothing moves) when the radius is smaller than
/// the distance from the anchor to every corner of its triangle, now and at rest.
class BrushStroke {
public:
    /// `positions`: the mesh's positions when the drag starts (copied: only the region
    /// and its one-ring are kept). `stroke.drag` is ignored here. `topology` must outlive
    /// the stroke. update() is const and keeps no state, so it may run on any thread. Throws std::invalid_argument when the anchor triangle is out of range
    /// or the settings are invalid (radius <= 0, step outside (0, 1], iterations < 0;
    /// brush_settings_check.h has the full list), when `positions` does not hold
    /// topology.vertexCount() points, when the anchor is not finite, or when the stroke
    /// gives no anchor triangle and the mesh has none. Cost: the closest-point search when
    /// no triangle is given (O(#F), a few ms per 100k triangles), then work proportional
    /// to the region and its one-ring; nothing else of size #V is allocated.
    BrushStroke(const BrushTopology& topology, std::span<const glm::vec3> positions, const Stroke& stroke);

    /// Positions after dragging the anchor by `drag` (object space): warp, then Laplacian
    /// smoothing restricted to the region, written into `positions` (which must hold the
    /// start positions outside the region; only region vertices are written).
    /// Throws std::invalid_argument when `positions` does not hold #V points or `drag` is
    /// not finite.
    void update(const glm::dvec3& drag, std::span<glm::vec3> positions) const;

    [[nodiscard]] const InfluenceRegion& region() const { return m_region; }
    /// The anchor as resolved on the surface (closest point when the stroke gave none).
    [[nodiscard]] glm::dvec3 anchor() const { return m_anchor; }
    [[nodiscard]] std::uint32_t anchorTriangle() const { return m_anchorTriangle; }
    /// The stroke with anchor and anchorTriangle resolved and `drag` set: what the timeline
    /// records and what a replay applies.
    [[nodiscard]] Stroke committed(const glm::dvec3& drag) const;

private:
    const BrushTopology* m_topology;
    BrushSettings m_settings;
    glm::dvec3 m_anchor{0.0};
    std::uint32_t m_anchorTriangle = 0;
    glm::dvec3 m_anchorNormal{0.0}; ///< interpolated vertex normal at the anchor, at drag start
    InfluenceRegion m_region;
    RegionPatch m_patch;                   ///< the region and its one-ring, numbered locally
    std::vector<glm::dvec3> m_start;       ///< per patch vertex: its position at drag start
    std::vector<glm::vec3> m_startNormals; ///< per region vertex, angle-weighted, at drag start
    std::vector<double> m_smoothingSteps;  ///< per region vertex: λ·f, the smoothing step there
};

/// Applies a complete stroke to `positions` (in place). Returns the moved vertices
/// (sorted): the region's vertices, every one that may have been written (pass them to
/// updateRegionNormals in region_normals.h). Equivalent to
/// BrushStroke(topology, positions, stroke).update(stroke.drag), and throws like them.
std::vector<std::uint32_t> applyStroke(const BrushTopology& topology, std::span<glm::vec3> positions,
                                       const Stroke& stroke);

} // namespace trimlab::deform
