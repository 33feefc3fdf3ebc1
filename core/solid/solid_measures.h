#pragma once
/// \file
/// What Mesh Statistics measures of the trimmed solid (trimmed_solid.h): its volume, its
/// surface area and the area of its cross-section in each enabled clipping plane (the
/// area the cap covers). They are measured on the exact export, not on pixels, so they
/// hold at any zoom and agree with what `trimlab trim` writes.

#include "core/mesh/triangle_mesh.h"
#include "core/scene/scene.h"
#include "core/solid/trimmed_solid.h"
#include "core/trim/clip_plane.h"
#include "core/trim/trim_settings.h"
#include "core/util/task_control.h"

#include <cstddef>
#include <vector>

namespace trimlab {

/// Σ of the triangles' areas.
[[nodiscard]] double surfaceArea(const TriangleMesh& mesh);

/// The area of the section of the solid that the closed, outward-oriented `mesh` bounds
/// with the plane of `plane` (its enabled flag and side play no part): Green's theorem
/// over the segments where the triangles cross the plane, each run with the inside on its
/// left. A vertex on the plane counts as on its positive side, and the point on an edge
/// is computed from the edge's ends in one order, so that the triangles sharing the edge
/// agree and the segments close into loops. Overlapping or nested sections of a
/// self-crossing mesh add with their winding numbers.
[[nodiscard]] double crossSectionArea(const TriangleMesh& mesh, const ClipPlane& plane);

/// One enabled clipping plane's section of the solid.
struct PlaneSection {
    int plane = 0;     ///< index in ClipSet::planes
    double area = 0.0; ///< crossSectionArea of the solid
};

struct SolidMeasures {
    double volume = 0.0; ///< signed volume of the exported solid
    double area = 0.0;   ///< its surface area
    std::vector<PlaneSection> sections;
    TrimmedSolidStats stats;
};

/// The trimmed solid `settings` keeps of `scene` (trimmedSolid: the rule or the CSG, no
/// clipping) and its measures, a section for each enabled plane of settings.clipSet().
/// Throws as trimmedSolid does.
[[nodiscard]] SolidMeasures measureTrimmedSolid(const Scene& scene, const TrimSettings& settings,
                                                const TaskControl& control = {});

} // namespace trimlab
