#pragma once
/// \file
/// What an editable surface *is* before any edit (thesis 8.2: the designer deforms NURBS
/// and subdivision surfaces by moving their control points): a NURBS surface with its
/// tessellation density, or a subdivision cage with its level and mode. Plain,
/// serializable data (the project file stores it, core/timeline/surface_json.h); the
/// evaluator built from it is EditableSurface (editable_surface.h).
///
/// Control points. Both kinds expose one list of #C control points (object space,
/// double precision), the only thing an edit changes:
///  - NURBS: `surface.points` in the net's order (index j·countU + i, nurbs_surface.h).
///    Weights, knots, degrees and the closed flags are part of the definition and never
///    change through an edit. Tied points (seam twins, the points of a pole) are separate
///    control points that must always hold equal positions (edits move them together).
///  - Subdivision: `cage.positions` (index = cage vertex).

#include "core/surface/nurbs_surface.h"
#include "core/surface/subdivision_cage.h"
#include "core/surface/subdivision_surface.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace trimlab {

/// Which kind of surface a definition holds.
enum class SurfaceKind {
    Nurbs,       ///< NurbsDefinition
    Subdivision, ///< SubdivisionDefinition
};

/// "nurbs" / "subdivision" (project files, messages).
[[nodiscard]] std::string_view surfaceKindName(SurfaceKind kind);

/// Default tessellation density of NURBS surfaces (intervals per direction over the
/// whole domain; see nurbs_tessellation.h for how they are spread over knot spans).
inline constexpr int kDefaultNurbsSegmentsU = 48;
inline constexpr int kDefaultNurbsSegmentsV = 24;

/// A NURBS surface and how finely it is tessellated.
struct NurbsDefinition {
    NurbsSurface surface;                   ///< must pass requireValidNurbs
    int segmentsU = kDefaultNurbsSegmentsU; ///< 1..kMaxTessellationSegments
    int segmentsV = kDefaultNurbsSegmentsV; ///< 1..kMaxTessellationSegments

    friend bool operator==(const NurbsDefinition&, const NurbsDefinition&) = default;
};

/// A subdivision cage (its scheme, boundary rule and sharpness tags are cage fields)
/// and the level and mode of the tessellation.
struct SubdivisionDefinition {
    SubdivisionCage cage;         ///< must pass validateCage
    SubdivisionSettings settings; ///< level in [0, SubdivisionSurface::kMaxLevel]
};
/// Field-wise equality, doubles and floats compared by value (-0.0 == 0.0); the
/// SubdivisionCage has no operator== of its own, so it is compared here field by field.
[[nodiscard]] bool operator==(const SubdivisionDefinition& a, const SubdivisionDefinition& b);

/// A NURBS or a subdivision definition.
struct SurfaceDefinition {
    std::variant<NurbsDefinition, SubdivisionDefinition> source;

    [[nodiscard]] SurfaceKind kind() const
    {
        return source.index() == 0 ? SurfaceKind::Nurbs : SurfaceKind::Subdivision;
    }
    /// The NURBS definition; std::bad_variant_access for a subdivision definition.
    [[nodiscard]] const NurbsDefinition& nurbs() const { return std::get<NurbsDefinition>(source); }
    /// The subdivision definition; std::bad_variant_access for a NURBS definition.
    [[nodiscard]] const SubdivisionDefinition& subdivision() const { return std::get<SubdivisionDefinition>(source); }

    /// #C: control points of the NURBS net or cage vertices.
    [[nodiscard]] std::size_t controlPointCount() const;
    /// The #C control points before any edit (a copy; see the file comment).
    [[nodiscard]] std::vector<glm::dvec3> controlPoints() const;

    friend bool operator==(const SurfaceDefinition&, const SurfaceDefinition&) = default;
};

/// Convenience constructors.
[[nodiscard]] SurfaceDefinition nurbsDefinition(NurbsSurface surface, int segmentsU = kDefaultNurbsSegmentsU,
                                                int segmentsV = kDefaultNurbsSegmentsV);
[[nodiscard]] SurfaceDefinition subdivisionDefinition(SubdivisionCage cage, SubdivisionSettings settings = {});

/// What is wrong with `definition`, in one sentence that names the element ("NURBS:
/// weights[17]: ...", "subdivision: level 7 is outside 0 to 5", "NURBS: segmentsU 0 is
/// outside 1 to 8192"); nullopt when it can be built. Cheap: validates the data
/// (requireValidNurbs / validateCage) but builds no tessellation, so a definition that
/// passes can still be refused by the tessellators for its size (kMaxTessellationSamples,
/// SubdivisionSurface::kMaxTriangles).
[[nodiscard]] std::optional<std::string> findSurfaceDefinitionProblem(const SurfaceDefinition& definition);

/// Throws std::invalid_argument "<caller>: <problem>" when findSurfaceDefinitionProblem
/// reports one.
void requireValidSurfaceDefinition(const SurfaceDefinition& definition, const std::string& caller);

/// The control points tied to control point `index` (NURBS seam twins and pole points,
/// linkedControlPoints in nurbs_surface.h, judged on the definition's own net), `index`
/// included, sorted ascending; `{index}` for subdivision cages (no ties); empty for an
/// index >= controlPointCount(). Edits must give all of them the same position.
[[nodiscard]] std::vector<std::uint32_t> tiedControlPoints(const SurfaceDefinition& definition, std::uint32_t index);

} // namespace trimlab
