#include "core/timeline/view_settings_json.h"

#include "core/io/json_fields.h"

#include <glm/geometric.hpp>

#include <cstddef>

namespace trimlab::timeline {

using io::dvec3Json;
using io::dvec3Value;
using io::fieldPath;
using io::finiteNumber;
using io::indexPath;
using io::JsonPathError;
using io::jsonTypeText;
using io::optionalField;
using io::requireArray;
using io::requireObject;
using io::stringValue;
using nlohmann::json;

namespace {

bool booleanValue(const json& value, const std::string& path)
{
    if (!value.is_boolean())
        throw JsonPathError(path, "must be true or false, not " + jsonTypeText(value));
    return value.get<bool>();
}

/// Calls `read(field, fieldPath)` when `key` is present in `object`.
template <class Read>
void readOptional(const json& object, std::string_view key, const std::string& path, Read&& read)
{
    if (const json* field = optionalField(object, key))
        read(*field, fieldPath(path, key));
}

/// A number within the range of the parameter table's `row` (the Render panel's and the
/// command line's range of the same setting).
double numberInRow(const json& value, const ParameterSpec& row, const std::string& path)
{
    const double number = finiteNumber(value, path);
    if (number < row.min || number > row.max)
        throw JsonPathError(path, "must be " + parameterRangeText(row));
    return number;
}

json clipJson(const RelativeClipPlane& plane)
{
    return json{
        {"enabled", plane.enabled}, {"normal", dvec3Json(plane.normal)}, {"centre_distance", plane.centreDistance}};
}

RelativeClipPlane readClip(const json& value, const std::string& path)
{
    requireObject(value, path);
    RelativeClipPlane plane;
    readOptional(value, "enabled", path,
                 [&](const json& v, const std::string& p) { plane.enabled = booleanValue(v, p); });
    readOptional(value, "normal", path, [&](const json& v, const std::string& p) {
        plane.normal = dvec3Value(v, p);
        const double length = glm::length(plane.normal);
        if (!(length > 0.0))
            throw JsonPathError(p, "must not be the zero vector");
        plane.normal /= length;
    });
    readOptional(value, "centre_distance", path,
                 [&](const json& v, const std::string& p) { plane.centreDistance = finiteNumber(v, p); });
    return plane;
}

json capJson(const StoredViewSettings& settings)
{
    return json{{"enabled", settings.capEnabled},
                {"pattern", std::string(capPatternName(settings.capPattern))},
                {"spacing_fraction", settings.capSpacingFraction}};
}

void readCap(const json& value, const std::string& path, StoredViewSettings& settings)
{
    requireObject(value, path);
    readOptional(value, "enabled", path,
                 [&](const json& v, const std::string& p) { settings.capEnabled = booleanValue(v, p); });
    readOptional(value, "pattern", path, [&](const json& v, const std::string& p) {
        const std::string name = stringValue(v, p);
        const std::optional<CapPattern> pattern = parseCapPattern(name);
        if (!pattern)
            throw JsonPathError(p, "unknown cap pattern '" + name + "' (known: hatched, striped, solid)");
        settings.capPattern = *pattern;
    });
    readOptional(value, "spacing_fraction", path, [&](const json& v, const std::string& p) {
        settings.capSpacingFraction = numberInRow(v, inspect_parameters::kCapSpacing, p);
    });
}

json transparencyJson(const TransparencySettings& xray)
{
    return json{{"enabled", xray.enabled},        {"display", std::string(trimDisplayName(xray.display))},
                {"layer_alpha", xray.layerAlpha}, {"ghost_alpha", xray.ghostAlpha},
                {"density", xray.density},        {"fresnel_exponent", xray.fresnelExponent}};
}

void readTransparency(const json& value, const std::string& path, TransparencySettings& xray)
{
    requireObject(value, path);
    readOptional(value, "enabled", path,
                 [&](const json& v, const std::string& p) { xray.enabled = booleanValue(v, p); });
    readOptional(value, "display", path, [&](const json& v, const std::string& p) {
        const std::string name = stringValue(v, p);
        const std::optional<TrimDisplay> display = parseTrimDisplay(name);
        if (!display)
            throw JsonPathError(p, "unknown display '" + name + "' (known: opaque, translucent)");
        xray.display = *display;
    });
    readOptional(value, "layer_alpha", path, [&](const json& v, const std::string& p) {
        xray.layerAlpha = numberInRow(v, inspect_parameters::kLayerAlpha, p);
    });
    readOptional(value, "ghost_alpha", path, [&](const json& v, const std::string& p) {
        xray.ghostAlpha = numberInRow(v, inspect_parameters::kGhostAlpha, p);
    });
    readOptional(value, "density", path, [&](const json& v, const std::string& p) {
        xray.density = numberInRow(v, inspect_parameters::kDensity, p);
    });
    readOptional(value, "fresnel_exponent", path, [&](const json& v, const std::string& p) {
        xray.fresnelExponent = numberInRow(v, inspect_parameters::kFresnel, p);
    });
}

} // namespace

json viewSettingsJson(const StoredViewSettings& settings)
{
    json clips = json::array();
    for (const RelativeClipPlane& plane : settings.clips)
        clips.push_back(clipJson(plane));
    return json{
        {"trim", settings.trimEnabled},
        {"classification", std::string(classificationName(settings.classification))},
        {"clips", std::move(clips)},
        {"cap", capJson(settings)},
        {"highlight", json{{"collisions", settings.highlight.collisions}, {"coplanar", settings.highlight.coplanar}}},
        {"transparency", transparencyJson(settings.transparency)}};
}

StoredViewSettings readViewSettings(const json& value, const std::string& path)
{
    requireObject(value, path);
    StoredViewSettings settings;
    readOptional(value, "trim", path,
                 [&](const json& v, const std::string& p) { settings.trimEnabled = booleanValue(v, p); });
    readOptional(value, "classification", path, [&](const json& v, const std::string& p) {
        const std::string name = stringValue(v, p);
        const std::optional<Classification> classification = parseClassification(name);
        if (!classification)
            throw JsonPathError(p, "unknown classification '" + name + "' (known: static, dynamic)");
        settings.classification = *classification;
    });
    readOptional(value, "clips", path, [&](const json& v, const std::string& p) {
        requireArray(v, p);
        if (v.size() > settings.clips.size())
            throw JsonPathError(p, "has " + std::to_string(v.size()) + " planes; at most " +
                                       std::to_string(settings.clips.size()));
        for (std::size_t i = 0; i < v.size(); ++i)
            settings.clips[i] = readClip(v[i], indexPath(p, i));
    });
    readOptional(value, "cap", path, [&](const json& v, const std::string& p) { readCap(v, p, settings); });
    readOptional(value, "highlight", path, [&](const json& v, const std::string& p) {
        requireObject(v, p);
        readOptional(v, "collisions", p,
                     [&](const json& b, const std::string& q) { settings.highlight.collisions = booleanValue(b, q); });
        readOptional(v, "coplanar", p,
                     [&](const json& b, const std::string& q) { settings.highlight.coplanar = booleanValue(b, q); });
    });
    readOptional(value, "transparency", path,
                 [&](const json& v, const std::string& p) { readTransparency(v, p, settings.transparency); });
    return settings;
}

} // namespace trimlab::timeline
