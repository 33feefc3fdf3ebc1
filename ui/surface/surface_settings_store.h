#pragma once
/// \file
/// The Surface panel's choices (keys "surface/…") in a QSettings: the tessellation
/// density of new NURBS surfaces, the patch degree, the subdivision scheme, level and
/// mode, whether the control net is shown, and the step of "Move along normal" (as a
/// fraction of the surface's bounding radius, for the reason brush_settings_store.h gives).
/// Missing or unusable values fall back field by field to SurfaceChoices' defaults.

#include "core/surface/subdivision_cage.h"
#include "core/surface/subdivision_surface.h"

class QSettings;

namespace trimlab::ui {

struct SurfaceChoices {
    /// Intervals along u / v of a NURBS tessellation (NurbsTessellation's segments).
    int segmentsU = 32;
    int segmentsV = 16;
    /// Degree in u and v of a new NURBS patch.
    int patchDegree = 3;
    /// Subdivision scheme for cages read from files (built-in cages bring their own).
    SubdivisionScheme scheme = SubdivisionScheme::CatmullClark;
    int level = 3;
    SubdivisionMode mode = SubdivisionMode::Limit;
    bool showNet = true;
    /// "Move along normal" distance / bounding radius of the surface.
    double normalStepFraction = 0.1;

    static constexpr int kMinSegments = 2;
    static constexpr int kMaxSegments = 256;
    static constexpr int kMaxPatchDegree = 5;
    static constexpr double kMaxNormalStepFraction = 2.0;

    friend bool operator==(const SurfaceChoices&, const SurfaceChoices&) = default;
};

[[nodiscard]] SurfaceChoices loadSurfaceChoices(const QSettings& settings);
void saveSurfaceChoices(QSettings& settings, const SurfaceChoices& choices);

} // namespace trimlab::ui
