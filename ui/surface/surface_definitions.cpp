#include "ui/surface/surface_definitions.h"

#include "core/surface/nurbs_primitives.h"

#include <QLocale>

#include <stdexcept>
#include <string>

namespace trimlab::ui {

namespace {

constexpr std::array kPrimitives{NurbsPrimitive::Sphere, NurbsPrimitive::Torus, NurbsPrimitive::Tube,
                                 NurbsPrimitive::Patch};
constexpr int kPatchPoints = 6;

/// Uniform clamped knots on [0, 1]: degree+1 zeros, count−degree−1 interior knots, degree+1 ones.
std::vector<double> uniformClampedKnots(int count, int degree)
{
    std::vector<double> knots(std::size_t(count + degree + 1), 0.0);
    const int spans = count - degree;
    for (int k = 1; k < spans; ++k)
        knots[std::size_t(degree + k)] = double(k) / double(spans);
    for (int k = 0; k <= degree; ++k)
        knots[std::size_t(count + k)] = 1.0;
    return knots;
}

/// The patch turned from the xz plane (normal +y) into the xy plane (normal +z).
NurbsSurface frontFacingPatch(int degree)
{
    NurbsSurface patch = makeNurbsPatch(glm::dvec3(0.0), 2.0, 2.0, kPatchPoints, kPatchPoints);
    for (glm::dvec3& p : patch.points)
        p = glm::dvec3(p.x, -p.z, p.y);
    patch.degreeU = patch.degreeV = degree;
    patch.knotsU = uniformClampedKnots(patch.countU, degree);
    patch.knotsV = uniformClampedKnots(patch.countV, degree);
    return patch;
}

bool isPatch(const NurbsSurface& s)
{
    return !s.closedU && !s.closedV && !isPole(s, NurbsSide::UBegin) && !isPole(s, NurbsSide::UEnd) &&
           !isPole(s, NurbsSide::VBegin) && !isPole(s, NurbsSide::VEnd);
}

} // namespace

std::span<const NurbsPrimitive> nurbsPrimitives()
{
    return kPrimitives;
}

QString nurbsPrimitiveLabel(NurbsPrimitive primitive)
{
    switch (primitive) {
    case NurbsPrimitive::Sphere:
        return QObject::tr("Sphere");
    case NurbsPrimitive::Torus:
        return QObject::tr("Torus");
    case NurbsPrimitive::Tube:
        return QObject::tr("Tube (capped)");
    case NurbsPrimitive::Patch:
        return QObject::tr("Patch");
    }
    return {};
}

QString nurbsPrimitiveKey(NurbsPrimitive primitive)
{
    switch (primitive) {
    case NurbsPrimitive::Sphere:
        return QStringLiteral("Sphere");
    case NurbsPrimitive::Torus:
        return QStringLiteral("Torus");
    case NurbsPrimitive::Tube:
        return QStringLiteral("Tube");
    case NurbsPrimitive::Patch:
        return QStringLiteral("Patch");
    }
    return {};
}

SurfaceDefinition makePrimitiveDefinition(NurbsPrimitive primitive, const SurfaceChoices& choices)
{
    const glm::dvec3 origin(0.0);
    NurbsSurface surface;
    switch (primitive) {
    case NurbsPrimitive::Sphere:
        surface = makeNurbsSphere(origin, 1.0);
        break;
    case NurbsPrimitive::Torus:
        surface = makeNurbsTorus(origin, 1.0, 0.4);
        break;
    case NurbsPrimitive::Tube:
        surface = makeNurbsCappedTube(origin, 0.6, 1.6);
        break;
    case NurbsPrimitive::Patch:
        surface = frontFacingPatch(choices.patchDegree);
        break;
    }
    return nurbsDefinition(std::move(surface), choices.segmentsU, choices.segmentsV);
}

QString builtInCageLabel(const QString& name)
{
    if (name == QLatin1String("cube"))
        return QObject::tr("Cube");
    if (name == QLatin1String("torus"))
        return QObject::tr("Torus");
    if (name == QLatin1String("t-shape"))
        return QObject::tr("T-Shape");
    if (name == QLatin1String("tetrahedron"))
        return QObject::tr("Tetrahedron (Loop)");
    if (name == QLatin1String("octahedron"))
        return QObject::tr("Octahedron (Loop)");
    return name;
}

SurfaceChoices choicesShowing(const SurfaceDefinition& definition, SurfaceChoices choices)
{
    if (definition.kind() == SurfaceKind::Nurbs) {
        const NurbsDefinition& nurbs = definition.nurbs();
        choices.segmentsU = nurbs.segmentsU;
        choices.segmentsV = nurbs.segmentsV;
        if (isPatch(nurbs.surface))
            choices.patchDegree = nurbs.surface.degreeU;
    } else {
        const SubdivisionDefinition& subdivision = definition.subdivision();
        choices.level = subdivision.settings.level;
        choices.mode = subdivision.settings.mode;
        choices.scheme = subdivision.cage.scheme;
    }
    return choices;
}

SurfacePanel::Kind panelKind(const SurfaceDefinition& definition)
{
    if (definition.kind() == SurfaceKind::Subdivision)
        return SurfacePanel::Kind::Subdivision;
    return isPatch(definition.nurbs().surface) ? SurfacePanel::Kind::NurbsPatch : SurfacePanel::Kind::Nurbs;
}

QString describeSurface(const EditableSurface& surface, const QString& name)
{
    const QLocale locale;
    const QString triangles = locale.toString(qulonglong(surface.mesh().triangles.size()));
    const SurfaceDefinition& definition = surface.definition();
    if (definition.kind() == SurfaceKind::Nurbs) {
        const NurbsSurface& s = definition.nurbs().surface;
        return QObject::tr("%1 — NURBS, degree %2 × %3, %4 × %5 control points; %6 triangles")
            .arg(name)
            .arg(s.degreeU)
            .arg(s.degreeV)
            .arg(s.countU)
            .arg(s.countV)
            .arg(triangles);
    }
    const SubdivisionDefinition& d = definition.subdivision();
    return QObject::tr("%1 — %2 subdivision, cage of %3 vertices, level %4; %5 triangles")
        .arg(name)
        .arg(d.cage.scheme == SubdivisionScheme::Loop ? QObject::tr("Loop") : QObject::tr("Catmull–Clark"))
        .arg(surface.controlPointCount())
        .arg(d.settings.level)
        .arg(triangles);
}

SurfaceDefinition rebuiltDefinition(const SurfaceDefinition& definition, std::span<const glm::dvec3> controlPoints,
                                    const SurfaceChoices& choices)
{
    if (controlPoints.size() != definition.controlPointCount())
        throw std::invalid_argument("the history has " + std::to_string(controlPoints.size()) +
                                    " control points, the surface " + std::to_string(definition.controlPointCount()));
    SurfaceDefinition rebuilt = definition;
    if (rebuilt.kind() == SurfaceKind::Nurbs) {
        NurbsDefinition& nurbs = std::get<NurbsDefinition>(rebuilt.source);
        nurbs.surface.points.assign(controlPoints.begin(), controlPoints.end());
        nurbs.segmentsU = choices.segmentsU;
        nurbs.segmentsV = choices.segmentsV;
        NurbsSurface& s = nurbs.surface;
        if (isPatch(s) && (s.degreeU != choices.patchDegree || s.degreeV != choices.patchDegree)) {
            if (choices.patchDegree + 1 > s.countU || choices.patchDegree + 1 > s.countV)
                throw std::invalid_argument("degree " + std::to_string(choices.patchDegree) + " needs at least " +
                                            std::to_string(choices.patchDegree + 1) + " control points per row");
            s.degreeU = s.degreeV = choices.patchDegree;
            s.knotsU = uniformClampedKnots(s.countU, s.degreeU);
            s.knotsV = uniformClampedKnots(s.countV, s.degreeV);
        }
    } else {
        SubdivisionDefinition& subdivision = std::get<SubdivisionDefinition>(rebuilt.source);
        subdivision.cage.positions.assign(controlPoints.begin(), controlPoints.end());
        subdivision.settings = SubdivisionSettings{choices.level, choices.mode};
        subdivision.cage.scheme = choices.scheme;
    }
    requireValidSurfaceDefinition(rebuilt, "Rebuild");
    return rebuilt;
}

} // namespace trimlab::ui
