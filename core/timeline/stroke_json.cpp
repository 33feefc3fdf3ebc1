#include "core/timeline/stroke_json.h"

#include "core/io/json_fields.h"
#include "core/timeline/stroke_validation.h"

#include <limits>
#include <stdexcept>

namespace trimlab::timeline {

using io::dvec3Json;
using io::dvec3Value;
using io::fieldPath;
using io::finiteNumber;
using io::integerInRange;
using io::JsonPathError;
using io::optionalField;
using io::rejectUnknownFields;
using io::requiredField;
using io::requireObject;
using io::stringValue;

namespace {

deform::FalloffProfile readProfile(const nlohmann::json& value, const std::string& path)
{
    const std::string name = stringValue(value, path);
    if (const auto profile = deform::parseFalloffProfile(name))
        return *profile;
    throw JsonPathError(path, "unknown profile '" + name + "' (known: smooth, linear, sharp)");
}

deform::SmoothingWeights readWeights(const nlohmann::json& value, const std::string& path)
{
    const std::string name = stringValue(value, path);
    if (const auto weights = deform::parseSmoothingWeights(name))
        return *weights;
    throw JsonPathError(path, "unknown smoothing weights '" + name + "' (known: uniform, cotangent)");
}

void readSmoothing(const nlohmann::json& value, const std::string& path, bool rejectUnknown,
                   deform::BrushSettings& brush)
{
    requireObject(value, path);
    if (rejectUnknown)
        rejectUnknownFields(value, {"iterations", "weights", "step"}, path);
    if (const nlohmann::json* v = optionalField(value, "iterations"))
        brush.smoothingIterations = int(integerInRange(*v, 0, kMaxSmoothingIterations, fieldPath(path, "iterations")));
    if (const nlohmann::json* v = optionalField(value, "weights"))
        brush.smoothingWeights = readWeights(*v, fieldPath(path, "weights"));
    if (const nlohmann::json* v = optionalField(value, "step")) {
        brush.smoothingStep = finiteNumber(*v, fieldPath(path, "step"));
        if (!(brush.smoothingStep > 0.0 && brush.smoothingStep <= 1.0))
            throw JsonPathError(fieldPath(path, "step"), "must be in (0, 1]");
    }
}

void readBrush(const nlohmann::json& value, const std::string& path, bool rejectUnknown, deform::BrushSettings& brush)
{
    if (const nlohmann::json* v = optionalField(value, "radius")) {
        brush.radius = finiteNumber(*v, fieldPath(path, "radius"));
        if (!(brush.radius > 0.0))
            throw JsonPathError(fieldPath(path, "radius"), "must be > 0");
    }
    if (const nlohmann::json* v = optionalField(value, "strength"))
        brush.strength = finiteNumber(*v, fieldPath(path, "strength"));
    if (const nlohmann::json* v = optionalField(value, "profile"))
        brush.profile = readProfile(*v, fieldPath(path, "profile"));
    if (const nlohmann::json* v = optionalField(value, "smoothing"))
        readSmoothing(*v, fieldPath(path, "smoothing"), rejectUnknown, brush);
}

} // namespace

nlohmann::json strokeJson(const deform::Stroke& stroke)
{
    if (const std::string problem = strokeProblem(stroke); !problem.empty())
        throw std::invalid_argument("strokeJson: " + problem);
    nlohmann::json json = nlohmann::json::object();
    json["anchor"] = dvec3Json(stroke.anchor);
    if (stroke.anchorTriangle)
        json["triangle"] = *stroke.anchorTriangle;
    json["drag"] = dvec3Json(stroke.drag);
    json["radius"] = stroke.brush.radius;
    json["strength"] = stroke.brush.strength;
    json["profile"] = std::string(deform::falloffProfileName(stroke.brush.profile));
    json["smoothing"] = {{"iterations", stroke.brush.smoothingIterations},
                         {"weights", std::string(deform::smoothingWeightsName(stroke.brush.smoothingWeights))},
                         {"step", stroke.brush.smoothingStep}};
    return json;
}

deform::Stroke readStrokeJson(const nlohmann::json& value, const std::string& path, bool rejectUnknown)
{
    requireObject(value, path);
    if (rejectUnknown)
        rejectUnknownFields(value, {"anchor", "triangle", "drag", "radius", "strength", "profile", "smoothing"}, path);
    deform::Stroke stroke;
    stroke.anchor = dvec3Value(requiredField(value, "anchor", path), fieldPath(path, "anchor"));
    if (const nlohmann::json* v = optionalField(value, "triangle"))
        stroke.anchorTriangle = std::uint32_t(
            integerInRange(*v, 0, std::numeric_limits<std::uint32_t>::max(), fieldPath(path, "triangle")));
    stroke.drag = dvec3Value(requiredField(value, "drag", path), fieldPath(path, "drag"));
    readBrush(value, path, rejectUnknown, stroke.brush);
    return stroke;
}

} // namespace trimlab::timeline
