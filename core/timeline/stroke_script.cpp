#include "core/timeline/stroke_script.h"

#include "core/io/atomic_write.h"
#include "core/io/file_bytes.h"
#include "core/io/json_fields.h"
#include "core/timeline/stroke_json.h"

#include <nlohmann/json.hpp>

#include <limits>
#include <stdexcept>
#include <string>

namespace trimlab::timeline {

using io::fieldPath;
using io::indexPath;
using io::integerInRange;
using io::JsonPathError;
using io::JsonSyntaxError;
using io::optionalField;
using io::parseJsonText;
using io::readFileBytes;
using io::rejectUnknownFields;
using io::requireArray;
using io::requiredField;
using io::requireObject;
using io::stringValue;
using io::writeFileAtomically;

namespace {

using nlohmann::json;

std::string errorText(const std::string& source, std::size_t line, std::size_t column, const std::string& path,
                      const std::string& reason)
{
    std::string text = source;
    if (line > 0)
        text += ":" + std::to_string(line) + ":" + std::to_string(column);
    text += ": ";
    if (!path.empty())
        text += path + ": ";
    return text + reason;
}

void checkHeader(const json& document)
{
    requireObject(document, "");
    rejectUnknownFields(document, {"format", "version", "sets"}, "");
    const std::string format = stringValue(requiredField(document, "format", ""), "format");
    if (format != kStrokeScriptFormatName)
        throw JsonPathError("format", "must be \"" + std::string(kStrokeScriptFormatName) + "\", not \"" + format +
                                          "\": not a TrimLab stroke script");
    const std::int64_t version =
        integerInRange(requiredField(document, "version", ""), 1, std::numeric_limits<std::int32_t>::max(), "version");
    if (version > kStrokeScriptVersion)
        throw JsonPathError("version", "version " + std::to_string(version) + " is newer than this TrimLab (" +
                                           std::to_string(kStrokeScriptVersion) + ")");
}

ScriptSet readSet(const json& value, const std::string& path)
{
    requireObject(value, path);
    rejectUnknownFields(value, {"rule", "strokes"}, path);
    ScriptSet set;
    if (const json* rule = optionalField(value, "rule")) {
        const std::string name = stringValue(*rule, fieldPath(path, "rule"));
        const auto parsed = parseDynamicRule(name);
        if (!parsed)
            throw JsonPathError(fieldPath(path, "rule"), "unknown rule '" + name +
                                                             "' (known: additive, subtractive, intersection, "
                                                             "confluent, homogeneous-confluent)");
        set.rule = *parsed;
    }
    const std::string strokesPath = fieldPath(path, "strokes");
    const json& strokes = requiredField(value, "strokes", path);
    requireArray(strokes, strokesPath);
    for (std::size_t i = 0; i < strokes.size(); ++i)
        set.strokes.push_back(readStrokeJson(strokes[i], indexPath(strokesPath, i), true));
    return set;
}

StrokeScript readScript(const json& document)
{
    checkHeader(document);
    const json& sets = requiredField(document, "sets", "");
    requireArray(sets, "sets");
    if (sets.empty())
        throw JsonPathError("sets", "must hold at least one set");
    StrokeScript script;
    for (std::size_t s = 0; s < sets.size(); ++s)
        script.sets.push_back(readSet(sets[s], indexPath("sets", s)));
    return script;
}

} // namespace

std::size_t StrokeScript::strokeCount() const
{
    std::size_t count = 0;
    for (const ScriptSet& set : sets)
        count += set.strokes.size();
    return count;
}

StrokeScriptError::StrokeScriptError(std::string source, std::string path, std::string reason, std::size_t line,
                                     std::size_t column)
    : std::runtime_error(errorText(source, line, column, path, reason)),
      m_source(std::move(source)),
      m_path(std::move(path)),
      m_reason(std::move(reason)),
      m_line(line),
      m_column(column)
{
}

std::optional<std::size_t> StrokeScriptError::line() const noexcept
{
    return m_line > 0 ? std::optional<std::size_t>(m_line) : std::nullopt;
}

std::optional<std::size_t> StrokeScriptError::column() const noexcept
{
    return m_line > 0 ? std::optional<std::size_t>(m_column) : std::nullopt;
}

StrokeScript parseStrokeScript(std::string_view text, const std::string& sourceName)
{
    json document;
    try {
        document = parseJsonText(text);
    } catch (const JsonSyntaxError& error) {
        const std::string what = error.truncated() ? "truncated JSON: " : "invalid JSON: ";
        throw StrokeScriptError(sourceName, "", what + error.reason(), error.position().line, error.position().column);
    }
    try {
        return readScript(document);
    } catch (const JsonPathError& error) {
        throw StrokeScriptError(sourceName, error.path(), error.reason());
    }
}

StrokeScript loadStrokeScript(const std::filesystem::path& path)
{
    std::string text;
    try {
        text = readFileBytes(path, kMaxStrokeScriptBytes);
    } catch (const std::runtime_error& error) {
        throw StrokeScriptError(path.string(), "", error.what());
    }
    return parseStrokeScript(text, path.string());
}

std::string strokeScriptJson(const StrokeScript& script)
{
    if (script.sets.empty())
        throw std::invalid_argument("strokeScriptJson: a script needs at least one set");
    json sets = json::array();
    for (const ScriptSet& set : script.sets) {
        json strokes = json::array();
        for (const deform::Stroke& stroke : set.strokes)
            strokes.push_back(strokeJson(stroke));
        sets.push_back(json{{"rule", std::string(dynamicRuleName(set.rule))}, {"strokes", std::move(strokes)}});
    }
    const json document{
        {"format", std::string(kStrokeScriptFormatName)}, {"version", kStrokeScriptVersion}, {"sets", std::move(sets)}};
    return document.dump(2) + "\n";
}

void writeStrokeScript(const std::filesystem::path& path, const StrokeScript& script)
{
    writeFileAtomically(path, strokeScriptJson(script));
}

StrokeScript strokeScriptFromTimeline(const Timeline& timeline)
{
    StrokeScript script;
    for (const DeformationSet& set : timeline.sets()) {
        ScriptSet scriptSet;
        scriptSet.rule = set.rule;
        for (int f = set.firstFrame; f < set.firstFrame + set.frameCount; ++f) {
            if (timeline.frame(f).isControlEdit())
                throw std::invalid_argument("frame " + std::to_string(f) +
                                            " is a control-point edit; a stroke script holds brush strokes only "
                                            "(save the history as a project instead)");
            scriptSet.strokes.push_back(timeline.frame(f).stroke);
        }
        script.sets.push_back(std::move(scriptSet));
    }
    if (script.sets.empty())
        script.sets.emplace_back(); // a default-constructed timeline: one empty confluent set
    return script;
}

} // namespace trimlab::timeline
