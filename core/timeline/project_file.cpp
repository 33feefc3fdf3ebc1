#include "core/timeline/project_file.h"

#include "core/timeline/control_edit.h"
#include "core/surface/editable_surface.h"
#include "core/io/atomic_write.h"
#include "core/timeline/binary_array.h"
#include "core/timeline/mesh_json.h"
#include "core/timeline/scene_json.h"
#include "core/io/file_bytes.h"
#include "core/io/json_fields.h"
#include "core/timeline/stroke_json.h"
#include "core/timeline/surface_json.h"
#include "core/timeline/view_settings_json.h"
#include "core/util/memory_budget.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <stdexcept>

namespace trimlab::timeline {

using io::dvec3Json;
using io::dvec3Value;
using io::fieldPath;
using io::finiteNumber;
using io::indexPath;
using io::integerInRange;
using io::JsonPathError;
using io::JsonSyntaxError;
using io::jsonTypeText;
using io::optionalField;
using io::parseJsonText;
using io::readFileBytes;
using io::requireArray;
using io::requiredField;
using io::requireObject;
using io::stringValue;
using io::writeFileAtomically;

namespace {

using nlohmann::json;

// ---- writing --------------------------------------------------------------------------

json framesJson(const Timeline& timeline)
{
    json frames = json::array();
    for (int f = 1; f < timeline.frameCount(); ++f) {
        const Frame& frame = timeline.frame(f);
        json item = json{{"vertices", uint32ArrayJson(frame.vertices)},
                         {"before", positionArrayJson(frame.before)},
                         {"after", positionArrayJson(frame.after)}};
        // A frame is a stroke or a control-point edit; the key says which.
        if (frame.isControlEdit())
            item["control_moves"] = controlMovesJson(frame.controlMoves);
        else
            item["stroke"] = strokeJson(frame.stroke);
        frames.push_back(std::move(item));
    }
    return frames;
}

json setsJson(const Timeline& timeline)
{
    json sets = json::array();
    for (const DeformationSet& set : timeline.sets())
        sets.push_back(json{{"rule", std::string(dynamicRuleName(set.rule))},
                            {"first_frame", set.firstFrame},
                            {"frame_count", set.frameCount}});
    return sets;
}

json viewJson(const ProjectView& view)
{
    for (const glm::dvec3& v : {view.eye, view.target, view.up}) {
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
            throw std::invalid_argument("projectJson: the view has a non-finite vector");
    }
    if (!(view.fovyDegrees > 0.0 && view.fovyDegrees < 180.0))
        throw std::invalid_argument("projectJson: the view's fovyDegrees must be in (0, 180)");
    return json{{"eye", dvec3Json(view.eye)},
                {"target", dvec3Json(view.target)},
                {"up", dvec3Json(view.up)},
                {"fovy_degrees", view.fovyDegrees}};
}

void writeExtras(json& document, const ProjectExtras& extras)
{
    if (extras.view)
        document["view"] = viewJson(*extras.view);
    if (extras.staticRule)
        document["static_rule"] = ruleName(*extras.staticRule);
    if (extras.viewSettings)
        document["view_settings"] = viewSettingsJson(*extras.viewSettings);
}

// The rules beyond the thesis's three arrived with version 3.
bool needsVersion3(const ProjectExtras& extras)
{
    if (!extras.staticRule)
        return false;
    const StaticRule rule = *extras.staticRule;
    return !(rule == StaticRule::Parity || rule == StaticRule::PositiveIndex || rule == StaticRule::AlternatingBorder);
}

// ---- reading --------------------------------------------------------------------------

// The document's version, after checking that it is a project this TrimLab reads.
std::int64_t checkFormat(const json& document)
{
    if (!document.is_object())
        throw JsonPathError("",
                            "not a TrimLab project (the document is " + jsonTypeText(document) + ", not an object)");
    const json* format = optionalField(document, "format");
    if (!format || !format->is_string() || format->get<std::string>() != kProjectFormatName)
        throw JsonPathError("",
                            "not a TrimLab project (\"format\" is not \"" + std::string(kProjectFormatName) + "\")");
    const std::int64_t version =
        integerInRange(requiredField(document, "version", ""), 1, std::numeric_limits<std::int32_t>::max(), "version");
    if (version > kProjectFormatVersion)
        throw JsonPathError("", "version " + std::to_string(version) + " is newer than this TrimLab (" +
                                    std::to_string(kProjectFormatVersion) + "); update TrimLab to open it");
    return version;
}

DynamicRule readRule(const json& value, const std::string& path)
{
    const std::string name = stringValue(value, path);
    if (const auto rule = parseDynamicRule(name))
        return *rule;
    throw JsonPathError(path, "unknown rule '" + name +
                                  "' (known: additive, subtractive, intersection, confluent, homogeneous-confluent)");
}

std::vector<DeformationSet> readSets(const json& value, const std::string& path)
{
    requireArray(value, path);
    std::vector<DeformationSet> sets;
    for (std::size_t s = 0; s < value.size(); ++s) {
        const std::string setPath = indexPath(path, s);
        const json& item = value[s];
        requireObject(item, setPath);
        DeformationSet set;
        set.rule = readRule(requiredField(item, "rule", setPath), fieldPath(setPath, "rule"));
        const std::int64_t maxInt = std::numeric_limits<std::int32_t>::max();
        set.firstFrame = int(
            integerInRange(requiredField(item, "first_frame", setPath), 1, maxInt, fieldPath(setPath, "first_frame")));
        set.frameCount = int(
            integerInRange(requiredField(item, "frame_count", setPath), 0, maxInt, fieldPath(setPath, "frame_count")));
        sets.push_back(set);
    }
    return sets;
}

std::vector<Frame> readFrames(const json& value, const std::string& path)
{
    requireArray(value, path);
    std::vector<Frame> frames;
    frames.reserve(value.size());
    for (std::size_t f = 0; f < value.size(); ++f) {
        const std::string framePath = indexPath(path, f);
        const json& item = value[f];
        requireObject(item, framePath);
        Frame frame;
        if (const json* moves = optionalField(item, "control_moves")) {
            if (optionalField(item, "stroke"))
                throw JsonPathError(framePath, "has both 'stroke' and 'control_moves'; a frame is one or the other");
            frame.controlMoves = readControlMoves(*moves, fieldPath(framePath, "control_moves"));
        } else {
            frame.stroke =
                readStrokeJson(requiredField(item, "stroke", framePath), fieldPath(framePath, "stroke"), false);
        }
        frame.vertices = readUint32Array(requiredField(item, "vertices", framePath), fieldPath(framePath, "vertices"));
        frame.before = readPositionArray(requiredField(item, "before", framePath), fieldPath(framePath, "before"));
        frame.after = readPositionArray(requiredField(item, "after", framePath), fieldPath(framePath, "after"));
        frames.push_back(std::move(frame));
    }
    return frames;
}

ProjectView readView(const json& value, const std::string& path)
{
    requireObject(value, path);
    ProjectView view;
    view.eye = dvec3Value(requiredField(value, "eye", path), fieldPath(path, "eye"));
    view.target = dvec3Value(requiredField(value, "target", path), fieldPath(path, "target"));
    view.up = dvec3Value(requiredField(value, "up", path), fieldPath(path, "up"));
    view.fovyDegrees = finiteNumber(requiredField(value, "fovy_degrees", path), fieldPath(path, "fovy_degrees"));
    if (!(view.fovyDegrees > 0.0 && view.fovyDegrees < 180.0))
        throw JsonPathError(fieldPath(path, "fovy_degrees"), "must be in (0, 180)");
    return view;
}

ProjectExtras readExtras(const json& document)
{
    ProjectExtras extras;
    if (const json* view = optionalField(document, "view"))
        extras.view = readView(*view, "view");
    if (const json* rule = optionalField(document, "static_rule")) {
        const std::string name = stringValue(*rule, "static_rule");
        extras.staticRule = parseStaticRule(name);
        if (!extras.staticRule)
            throw JsonPathError("static_rule",
                                "unknown static rule '" + name + "' (known: " + staticRuleNamesHelp() + ")");
    }
    if (const json* settings = optionalField(document, "view_settings"))
        extras.viewSettings = readViewSettings(*settings, "view_settings");
    return extras;
}

Project readDocument(const json& document)
{
    const std::int64_t version = checkFormat(document);
    if (const json* scene = version >= 3 ? optionalField(document, "scene") : nullptr) {
        Project project;
        project.scene = readScene(*scene, "scene");
        project.extras = readExtras(document);
        return project;
    }
    TriangleMesh base = readMesh(requiredField(document, "base_mesh", ""), "base_mesh");
    std::vector<DeformationSet> sets = readSets(requiredField(document, "sets", ""), "sets");
    std::vector<Frame> frames = readFrames(requiredField(document, "frames", ""), "frames");
    std::optional<SurfaceDefinition> surface;
    if (const json* value = optionalField(document, "surface"))
        surface = readSurfaceDefinition(*value, "surface");
    ProjectExtras extras = readExtras(document);
    try {
        Timeline timeline = Timeline::restore(std::move(base), std::move(frames), std::move(sets), std::move(surface));
        // Editing goes on from the stored base mesh as if it were the surface's
        // tessellation: a file where it is not is refused here, not at the first edit.
        if (timeline.surface())
            requireSurfaceMatchesTimeline(EditableSurface(*timeline.surface()), timeline);
        return Project{std::move(timeline), std::move(extras), std::nullopt};
    } catch (const std::invalid_argument& error) {
        throw JsonPathError("", std::string("inconsistent history: ") + error.what());
    } catch (const MemoryBudgetError& error) {
        throw JsonPathError("surface", error.what());
    }
}

} // namespace

std::string projectJson(const Timeline& timeline, const ProjectExtras& extras)
{
    json document = json::object();
    document["format"] = std::string(kProjectFormatName);
    // Plain mesh histories stay version 1, readable by every TrimLab; the surface parts
    // need version 2, a rule older TrimLabs do not know version 3.
    document["version"] = needsVersion3(extras) ? 3 : timeline.hasSurface() ? 2 : 1;
    document["generator"] = "TrimLab";
    if (timeline.surface())
        document["surface"] = surfaceDefinitionJson(*timeline.surface());
    document["base_mesh"] = meshJson(timeline.base());
    document["sets"] = setsJson(timeline);
    document["frames"] = framesJson(timeline);
    writeExtras(document, extras);
    return document.dump(1) + "\n";
}

std::string sceneProjectJson(const ProjectScene& scene, const ProjectExtras& extras)
{
    json document = json::object();
    document["format"] = std::string(kProjectFormatName);
    document["version"] = 3;
    document["generator"] = "TrimLab";
    document["scene"] = sceneJson(scene);
    writeExtras(document, extras);
    return document.dump(1) + "\n";
}

Project parseProject(std::string_view bytes, const std::string& displayName)
{
    json document;
    try {
        document = parseJsonText(bytes);
    } catch (const JsonSyntaxError& error) {
        const std::string at =
            "line " + std::to_string(error.position().line) + ", column " + std::to_string(error.position().column);
        if (error.truncated())
            throw ProjectFileError(displayName, "",
                                   "truncated: the JSON document ends early (" + at + ", byte " +
                                       std::to_string(bytes.size()) + "): " + error.reason());
        throw ProjectFileError(displayName, "", "not a TrimLab project: invalid JSON at " + at + ": " + error.reason());
    }
    try {
        return readDocument(document);
    } catch (const JsonPathError& error) {
        throw ProjectFileError(displayName, error.path(), error.reason());
    }
}

void saveProject(const Timeline& timeline, const std::filesystem::path& path, const ProjectExtras& extras)
{
    writeFileAtomically(path, projectJson(timeline, extras));
}

void saveSceneProject(const ProjectScene& scene, const std::filesystem::path& path, const ProjectExtras& extras)
{
    writeFileAtomically(path, sceneProjectJson(scene, extras));
}

Project readProject(const std::filesystem::path& path)
{
    std::string bytes;
    try {
        bytes = readFileBytes(path, kMaxProjectBytes);
    } catch (const std::runtime_error& error) {
        throw ProjectFileError(path.string(), "", error.what());
    }
    return parseProject(bytes, path.string());
}

bool isSceneProject(const std::filesystem::path& path)
{
    try {
        const json document = parseJsonText(readFileBytes(path, kMaxProjectBytes));
        return checkFormat(document) >= 3 && optionalField(document, "scene") != nullptr;
    } catch (const std::exception&) {
        return false;
    }
}

Project readHistoryProject(const std::filesystem::path& path)
{
    Project project = readProject(path);
    if (project.scene)
        throw ProjectFileError(path.string(), "scene",
                               "a scene of " + std::to_string(project.scene->objects.size()) +
                                   " object(s), not a deformation history");
    return project;
}

Timeline loadProject(const std::filesystem::path& path)
{
    return std::move(readHistoryProject(path).timeline);
}

} // namespace trimlab::timeline
