#include "core/surface/surface_definition.h"

#include "core/surface/nurbs_tessellation.h"

#include <limits>
#include <stdexcept>

namespace trimlab {

namespace {

bool sameCreases(const std::vector<CageCrease>& a, const std::vector<CageCrease>& b)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t k = 0; k < a.size(); ++k)
        if (a[k].a != b[k].a || a[k].b != b[k].b || a[k].sharpness != b[k].sharpness)
            return false;
    return true;
}

bool sameCorners(const std::vector<CageCorner>& a, const std::vector<CageCorner>& b)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t k = 0; k < a.size(); ++k)
        if (a[k].vertex != b[k].vertex || a[k].sharpness != b[k].sharpness)
            return false;
    return true;
}

std::optional<std::string> nurbsProblem(const NurbsDefinition& definition)
{
    if (const std::optional<NurbsProblem> problem = findNurbsProblem(definition.surface))
        return "NURBS: " + problem->where + ": " + problem->reason;
    for (const auto& [name, segments] :
         {std::pair{"segmentsU", definition.segmentsU}, std::pair{"segmentsV", definition.segmentsV}}) {
        if (segments < 1 || segments > kMaxTessellationSegments)
            return std::string("NURBS: ") + name + " " + std::to_string(segments) + " is outside 1 to " +
                   std::to_string(kMaxTessellationSegments);
    }
    return std::nullopt;
}

std::optional<std::string> subdivisionProblem(const SubdivisionDefinition& definition)
{
    const int level = definition.settings.level;
    if (level < 0 || level > SubdivisionSurface::kMaxLevel)
        return "subdivision: level " + std::to_string(level) + " is outside 0 to " +
               std::to_string(SubdivisionSurface::kMaxLevel);
    if (definition.cage.vertexCount() > std::size_t(std::numeric_limits<std::uint32_t>::max()))
        return std::string("subdivision: the cage has too many vertices");
    try {
        validateCage(definition.cage);
    } catch (const SubdivisionError& error) {
        return std::string("subdivision: ") + error.what();
    }
    return std::nullopt;
}

} // namespace

std::string_view surfaceKindName(SurfaceKind kind)
{
    return kind == SurfaceKind::Nurbs ? "nurbs" : "subdivision";
}

bool operator==(const SubdivisionDefinition& a, const SubdivisionDefinition& b)
{
    const SubdivisionCage& x = a.cage;
    const SubdivisionCage& y = b.cage;
    return x.positions == y.positions && x.faceSizes == y.faceSizes && x.faceIndices == y.faceIndices &&
           x.scheme == y.scheme && x.boundary == y.boundary && sameCreases(x.creases, y.creases) &&
           sameCorners(x.corners, y.corners) && a.settings.level == b.settings.level &&
           a.settings.mode == b.settings.mode;
}

std::size_t SurfaceDefinition::controlPointCount() const
{
    return kind() == SurfaceKind::Nurbs ? nurbs().surface.points.size() : subdivision().cage.positions.size();
}

std::vector<glm::dvec3> SurfaceDefinition::controlPoints() const
{
    return kind() == SurfaceKind::Nurbs ? nurbs().surface.points : subdivision().cage.positions;
}

SurfaceDefinition nurbsDefinition(NurbsSurface surface, int segmentsU, int segmentsV)
{
    return SurfaceDefinition{NurbsDefinition{std::move(surface), segmentsU, segmentsV}};
}

SurfaceDefinition subdivisionDefinition(SubdivisionCage cage, SubdivisionSettings settings)
{
    return SurfaceDefinition{SubdivisionDefinition{std::move(cage), settings}};
}

std::optional<std::string> findSurfaceDefinitionProblem(const SurfaceDefinition& definition)
{
    if (definition.kind() == SurfaceKind::Nurbs)
        return nurbsProblem(definition.nurbs());
    return subdivisionProblem(definition.subdivision());
}

void requireValidSurfaceDefinition(const SurfaceDefinition& definition, const std::string& caller)
{
    if (const std::optional<std::string> problem = findSurfaceDefinitionProblem(definition))
        throw std::invalid_argument(caller + ": " + *problem);
}

std::vector<std::uint32_t> tiedControlPoints(const SurfaceDefinition& definition, std::uint32_t index)
{
    if (index >= definition.controlPointCount())
        return {};
    if (definition.kind() == SurfaceKind::Subdivision)
        return {index};
    std::vector<std::uint32_t> tied;
    for (const std::size_t c : linkedControlPoints(definition.nurbs().surface, index))
        tied.push_back(std::uint32_t(c));
    return tied;
}

} // namespace trimlab
