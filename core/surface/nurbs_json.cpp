#include "core/surface/nurbs_json.h"

#include "core/surface/nurbs_basis.h"

#include "core/io/atomic_write.h"
#include "core/io/file_bytes.h"
#include "core/io/json_fields.h"

#include <nlohmann/json.hpp>

namespace trimlab {

namespace {

using io::indexPath;
using io::JsonPathError;
using nlohmann::json;

json surfaceJson(const NurbsSurface& s)
{
    json points = json::array();
    for (const glm::dvec3& p : s.points)
        points.push_back(io::dvec3Json(p));
    json object = json::object();
    object["name"] = s.name;
    object["degreeU"] = s.degreeU;
    object["degreeV"] = s.degreeV;
    object["countU"] = s.countU;
    object["countV"] = s.countV;
    object["closedU"] = s.closedU;
    object["closedV"] = s.closedV;
    object["knotsU"] = s.knotsU;
    object["knotsV"] = s.knotsV;
    object["points"] = std::move(points);
    object["weights"] = s.weights;
    return object;
}

bool booleanValue(const json& value, const std::string& path)
{
    if (!value.is_boolean())
        throw JsonPathError(path, "must be true or false, not " + io::jsonTypeText(value));
    return value.get<bool>();
}

// The array at object[key], which must have exactly `expected` elements.
const json& sizedArray(const json& object, const char* key, std::size_t expected, const std::string& what,
                       const std::string& path)
{
    const std::string at = io::fieldPath(path, key);
    const json& array = io::requiredField(object, key, path);
    io::requireArray(array, at);
    if (array.size() != expected)
        throw JsonPathError(at, std::to_string(array.size()) + " entries, but " + what + " = " +
                                    std::to_string(expected) + "; give exactly that many");
    return array;
}

std::vector<double> numbers(const json& array, const std::string& path)
{
    std::vector<double> values;
    values.reserve(array.size());
    for (std::size_t k = 0; k < array.size(); ++k)
        values.push_back(io::finiteNumber(array[k], indexPath(path, k)));
    return values;
}

// Degrees and counts, checked before any array is read, so that a file declaring a
// huge net is refused without allocating for it.
void readShape(const json& object, const std::string& path, NurbsSurface& s)
{
    const auto integer = [&](const char* key, std::int64_t low, std::int64_t high) {
        return int(io::integerInRange(io::requiredField(object, key, path), low, high, io::fieldPath(path, key)));
    };
    s.degreeU = integer("degreeU", 1, kMaxNurbsDegree);
    s.degreeV = integer("degreeV", 1, kMaxNurbsDegree);
    s.countU = integer("countU", 2, std::int64_t(kMaxNurbsControlPoints));
    s.countV = integer("countV", 2, std::int64_t(kMaxNurbsControlPoints));
    const std::size_t total = std::size_t(s.countU) * std::size_t(s.countV);
    if (total > kMaxNurbsControlPoints)
        throw JsonPathError(io::fieldPath(path, "countV"),
                            "countU·countV = " + std::to_string(total) + " control points are more than the limit of " +
                                std::to_string(kMaxNurbsControlPoints) + "; split the surface");
    if (const json* name = io::optionalField(object, "name"))
        s.name = io::stringValue(*name, io::fieldPath(path, "name"));
    if (const json* closed = io::optionalField(object, "closedU"))
        s.closedU = booleanValue(*closed, io::fieldPath(path, "closedU"));
    if (const json* closed = io::optionalField(object, "closedV"))
        s.closedV = booleanValue(*closed, io::fieldPath(path, "closedV"));
}

NurbsSurface readSurface(const json& object, const std::string& path)
{
    io::requireObject(object, path);
    io::rejectUnknownFields(object,
                            {"name", "degreeU", "degreeV", "countU", "countV", "closedU", "closedV", "knotsU", "knotsV",
                             "points", "weights"},
                            path);
    NurbsSurface s;
    readShape(object, path, s);
    const std::size_t total = std::size_t(s.countU) * std::size_t(s.countV);
    s.knotsU = numbers(sizedArray(object, "knotsU", std::size_t(s.countU + s.degreeU + 1), "countU+degreeU+1", path),
                       io::fieldPath(path, "knotsU"));
    s.knotsV = numbers(sizedArray(object, "knotsV", std::size_t(s.countV + s.degreeV + 1), "countV+degreeV+1", path),
                       io::fieldPath(path, "knotsV"));
    const json& points = sizedArray(object, "points", total, "countU·countV", path);
    s.points.reserve(total);
    for (std::size_t k = 0; k < total; ++k)
        s.points.push_back(io::dvec3Value(points[k], indexPath(io::fieldPath(path, "points"), k)));
    s.weights = numbers(sizedArray(object, "weights", total, "countU·countV", path), io::fieldPath(path, "weights"));
    if (const auto problem = findNurbsProblem(s))
        throw JsonPathError(io::fieldPath(path, problem->where), problem->reason);
    return s;
}

std::vector<NurbsSurface> readDocument(const json& document)
{
    io::requireObject(document, "");
    const json* format = io::optionalField(document, "format");
    if (!format || !format->is_string() || format->get<std::string>() != kNurbsFormatName)
        throw JsonPathError("format",
                            "not a TrimLab NURBS file (\"format\" is not \"" + std::string(kNurbsFormatName) + "\")");
    const auto version = io::integerInRange(io::requiredField(document, "version", ""), 1, 1'000'000, "version");
    if (version > kNurbsFormatVersion)
        throw JsonPathError("version", "version " + std::to_string(version) + " is newer than this TrimLab (" +
                                           std::to_string(kNurbsFormatVersion) + "); update TrimLab to open it");
    io::rejectUnknownFields(document, {"format", "version", "generator", "surfaces"}, "");
    const json& list = io::requiredField(document, "surfaces", "");
    io::requireArray(list, "surfaces");
    if (list.empty() || list.size() > kMaxNurbsSurfacesPerFile)
        throw JsonPathError("surfaces", "must hold 1 to " + std::to_string(kMaxNurbsSurfacesPerFile) +
                                            " surfaces, not " + std::to_string(list.size()));
    std::vector<NurbsSurface> surfaces;
    for (std::size_t k = 0; k < list.size(); ++k)
        surfaces.push_back(readSurface(list[k], indexPath("surfaces", k)));
    return surfaces;
}

} // namespace

std::string nurbsJson(std::span<const NurbsSurface> surfaces)
{
    if (surfaces.empty() || surfaces.size() > kMaxNurbsSurfacesPerFile)
        throw std::invalid_argument("nurbsJson: a file holds 1 to " + std::to_string(kMaxNurbsSurfacesPerFile) +
                                    " surfaces, not " + std::to_string(surfaces.size()));
    json list = json::array();
    for (std::size_t k = 0; k < surfaces.size(); ++k) {
        requireValidNurbs(surfaces[k], "nurbsJson: surfaces[" + std::to_string(k) + "]");
        list.push_back(surfaceJson(surfaces[k]));
    }
    json document = json::object();
    document["format"] = std::string(kNurbsFormatName);
    document["version"] = kNurbsFormatVersion;
    document["generator"] = "TrimLab";
    document["surfaces"] = std::move(list);
    return document.dump(1) + "\n";
}

void saveNurbsJson(const std::filesystem::path& path, std::span<const NurbsSurface> surfaces)
{
    io::writeFileAtomically(path, nurbsJson(surfaces));
}

std::vector<NurbsSurface> parseNurbsJson(std::string_view text, const std::string& displayName)
{
    return io::readJsonDocument<NurbsFileError>(text, displayName,
                                                [](const json& document) { return readDocument(document); });
}

std::vector<NurbsSurface> loadNurbsJson(const std::filesystem::path& path)
{
    std::string text;
    try {
        text = io::readFileBytes(path, kMaxNurbsFileBytes);
    } catch (const std::runtime_error& error) {
        throw NurbsFileError(path.string(), "", error.what());
    }
    return parseNurbsJson(text, path.string());
}

} // namespace trimlab
