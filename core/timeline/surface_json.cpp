#include "core/timeline/surface_json.h"

#include "core/surface/nurbs_json.h"
#include "core/timeline/binary_array.h"
#include "core/io/json_fields.h"

#include <limits>
#include <stdexcept>

namespace trimlab::timeline {

using io::fieldPath;
using io::finiteNumber;
using io::indexPath;
using io::integerInRange;
using io::JsonPathError;
using io::requireArray;
using io::requiredField;
using io::requireObject;
using io::stringValue;

namespace {

using nlohmann::json;

constexpr std::int64_t kMaxInt = std::numeric_limits<std::int32_t>::max();

std::string_view schemeName(SubdivisionScheme scheme)
{
    return scheme == SubdivisionScheme::Loop ? "loop" : "catmull-clark";
}

std::string_view boundaryName(BoundaryInterpolation boundary)
{
    return boundary == BoundaryInterpolation::EdgesOnly ? "edges-only" : "edges-and-corners";
}

std::string_view modeName(SubdivisionMode mode)
{
    return mode == SubdivisionMode::Uniform ? "uniform" : "limit";
}

json nurbsJsonObject(const NurbsDefinition& definition)
{
    const std::string text = nurbsJson(std::span(&definition.surface, 1));
    return json{{"kind", "nurbs"},
                {"nurbs", json::parse(text)},
                {"segments_u", definition.segmentsU},
                {"segments_v", definition.segmentsV}};
}

json subdivisionJsonObject(const SubdivisionDefinition& definition)
{
    const SubdivisionCage& cage = definition.cage;
    json creases = json::array();
    for (const CageCrease& crease : cage.creases)
        creases.push_back(json{{"a", crease.a}, {"b", crease.b}, {"sharpness", crease.sharpness}});
    json corners = json::array();
    for (const CageCorner& corner : cage.corners)
        corners.push_back(json{{"vertex", corner.vertex}, {"sharpness", corner.sharpness}});
    return json{{"kind", "subdivision"},
                {"scheme", std::string(schemeName(cage.scheme))},
                {"boundary", std::string(boundaryName(cage.boundary))},
                {"level", definition.settings.level},
                {"mode", std::string(modeName(definition.settings.mode))},
                {"positions", dvec3ArrayJson(cage.positions)},
                {"face_sizes", uint32ArrayJson(cage.faceSizes)},
                {"face_indices", uint32ArrayJson(cage.faceIndices)},
                {"creases", creases},
                {"corners", corners}};
}

NurbsDefinition readNurbs(const json& value, const std::string& path)
{
    const std::string nurbsPath = fieldPath(path, "nurbs");
    std::vector<NurbsSurface> surfaces;
    try {
        surfaces = parseNurbsJson(requiredField(value, "nurbs", path).dump(), "project");
    } catch (const NurbsFileError& error) {
        throw JsonPathError(error.where().empty() ? nurbsPath : nurbsPath + "." + error.where(), error.reason());
    }
    if (surfaces.size() != 1)
        throw JsonPathError(fieldPath(nurbsPath, "surfaces"),
                            "must hold exactly one surface, not " + std::to_string(surfaces.size()));
    NurbsDefinition definition{std::move(surfaces.front())};
    definition.segmentsU =
        int(integerInRange(requiredField(value, "segments_u", path), 1, kMaxInt, fieldPath(path, "segments_u")));
    definition.segmentsV =
        int(integerInRange(requiredField(value, "segments_v", path), 1, kMaxInt, fieldPath(path, "segments_v")));
    return definition;
}

template <typename Enum>
Enum readName(const json& object, std::string_view key, const std::string& path,
              std::initializer_list<std::pair<std::string_view, Enum>> names)
{
    const std::string where = fieldPath(path, key);
    const std::string name = stringValue(requiredField(object, key, path), where);
    std::string known;
    for (const auto& [text, value] : names) {
        if (text == name)
            return value;
        known += (known.empty() ? "" : ", ") + std::string(text);
    }
    throw JsonPathError(where, "unknown value '" + name + "' (known: " + known + ")");
}

float readSharpness(const json& item, const std::string& path)
{
    const std::string where = fieldPath(path, "sharpness");
    const double value = finiteNumber(requiredField(item, "sharpness", path), where);
    if (value < 0.0 || value > double(std::numeric_limits<float>::max()))
        throw JsonPathError(where, "must be >= 0 and a finite float");
    return float(value);
}

std::uint32_t readIndex(const json& item, std::string_view key, const std::string& path)
{
    return std::uint32_t(integerInRange(requiredField(item, key, path), 0, 0xffffffffLL, fieldPath(path, key)));
}

void readTags(const json& value, const std::string& path, SubdivisionCage& cage)
{
    const json& creases = requiredField(value, "creases", path);
    const std::string creasesPath = fieldPath(path, "creases");
    requireArray(creases, creasesPath);
    for (std::size_t k = 0; k < creases.size(); ++k) {
        const std::string itemPath = indexPath(creasesPath, k);
        requireObject(creases[k], itemPath);
        cage.creases.push_back({readIndex(creases[k], "a", itemPath), readIndex(creases[k], "b", itemPath),
                                readSharpness(creases[k], itemPath)});
    }
    const json& corners = requiredField(value, "corners", path);
    const std::string cornersPath = fieldPath(path, "corners");
    requireArray(corners, cornersPath);
    for (std::size_t k = 0; k < corners.size(); ++k) {
        const std::string itemPath = indexPath(cornersPath, k);
        requireObject(corners[k], itemPath);
        cage.corners.push_back({readIndex(corners[k], "vertex", itemPath), readSharpness(corners[k], itemPath)});
    }
}

SubdivisionDefinition readSubdivision(const json& value, const std::string& path)
{
    SubdivisionDefinition definition;
    SubdivisionCage& cage = definition.cage;
    cage.scheme = readName<SubdivisionScheme>(
        value, "scheme", path, {{"catmull-clark", SubdivisionScheme::CatmullClark}, {"loop", SubdivisionScheme::Loop}});
    cage.boundary = readName<BoundaryInterpolation>(value, "boundary", path,
                                                    {{"edges-only", BoundaryInterpolation::EdgesOnly},
                                                     {"edges-and-corners", BoundaryInterpolation::EdgesAndCorners}});
    definition.settings.level = int(integerInRange(requiredField(value, "level", path), 0,
                                                   SubdivisionSurface::kMaxLevel, fieldPath(path, "level")));
    definition.settings.mode = readName<SubdivisionMode>(
        value, "mode", path, {{"uniform", SubdivisionMode::Uniform}, {"limit", SubdivisionMode::Limit}});
    cage.positions = readDvec3Array(requiredField(value, "positions", path), fieldPath(path, "positions"));
    cage.faceSizes = readUint32Array(requiredField(value, "face_sizes", path), fieldPath(path, "face_sizes"));
    cage.faceIndices = readUint32Array(requiredField(value, "face_indices", path), fieldPath(path, "face_indices"));
    readTags(value, path, cage);
    return definition;
}

} // namespace

json surfaceDefinitionJson(const SurfaceDefinition& definition)
{
    requireValidSurfaceDefinition(definition, "surfaceDefinitionJson");
    if (definition.kind() == SurfaceKind::Nurbs)
        return nurbsJsonObject(definition.nurbs());
    return subdivisionJsonObject(definition.subdivision());
}

SurfaceDefinition readSurfaceDefinition(const json& value, const std::string& path)
{
    requireObject(value, path);
    const SurfaceKind kind = readName<SurfaceKind>(
        value, "kind", path, {{"nurbs", SurfaceKind::Nurbs}, {"subdivision", SurfaceKind::Subdivision}});
    SurfaceDefinition definition = kind == SurfaceKind::Nurbs ? SurfaceDefinition{readNurbs(value, path)}
                                                              : SurfaceDefinition{readSubdivision(value, path)};
    if (const std::optional<std::string> problem = findSurfaceDefinitionProblem(definition))
        throw JsonPathError(path, *problem);
    return definition;
}

json controlMovesJson(const std::vector<ControlPointMove>& moves)
{
    std::vector<std::uint32_t> indices;
    std::vector<glm::dvec3> before;
    std::vector<glm::dvec3> after;
    for (const ControlPointMove& move : moves) {
        indices.push_back(move.index);
        before.push_back(move.before);
        after.push_back(move.after);
    }
    return json{
        {"indices", uint32ArrayJson(indices)}, {"before", dvec3ArrayJson(before)}, {"after", dvec3ArrayJson(after)}};
}

std::vector<ControlPointMove> readControlMoves(const json& value, const std::string& path)
{
    requireObject(value, path);
    const std::vector<std::uint32_t> indices =
        readUint32Array(requiredField(value, "indices", path), fieldPath(path, "indices"));
    const std::vector<glm::dvec3> before =
        readDvec3Array(requiredField(value, "before", path), fieldPath(path, "before"));
    const std::vector<glm::dvec3> after = readDvec3Array(requiredField(value, "after", path), fieldPath(path, "after"));
    if (indices.empty())
        throw JsonPathError(fieldPath(path, "indices"), "must list at least one control point");
    if (before.size() != indices.size() || after.size() != indices.size())
        throw JsonPathError(path, "lists " + std::to_string(indices.size()) + " control points but " +
                                      std::to_string(before.size()) + " 'before' and " + std::to_string(after.size()) +
                                      " 'after' points");
    std::vector<ControlPointMove> moves(indices.size());
    for (std::size_t k = 0; k < moves.size(); ++k)
        moves[k] = {indices[k], before[k], after[k]};
    return moves;
}

} // namespace trimlab::timeline
