#pragma once
/// \file
/// Reading typed fields out of parsed JSON (nlohmann) with errors that name the JSON path
/// of the offending value, e.g. `sets[0].strokes[2].radius: must be > 0`. For TrimLab's
/// JSON document readers (projects, stroke scripts, skeletons, NURBS surfaces), which turn
/// JsonPathError into their own DocumentFileError, adding the file name.

#include <nlohmann/json.hpp>

#include <glm/vec3.hpp>

#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace trimlab::io {

/// A problem with the value at `path` ("" for the document itself).
class JsonPathError : public std::runtime_error {
public:
    JsonPathError(std::string path, std::string reason);
    [[nodiscard]] const std::string& path() const noexcept { return m_path; }
    [[nodiscard]] const std::string& reason() const noexcept { return m_reason; }

private:
    std::string m_path;
    std::string m_reason;
};

/// "parent.key" (or "key" when parent is empty) and "parent[i]".
[[nodiscard]] std::string fieldPath(const std::string& parent, std::string_view key);
[[nodiscard]] std::string indexPath(const std::string& parent, std::size_t index);

/// The JSON type of `value` in words ("a string", "an array", ...), for messages.
[[nodiscard]] std::string jsonTypeText(const nlohmann::json& value);

/// Throws unless `value` is an object / an array.
void requireObject(const nlohmann::json& value, const std::string& path);
void requireArray(const nlohmann::json& value, const std::string& path);
/// Throws naming the first key of `object` that is not in `allowed` (typo protection for
/// hand-written files).
void rejectUnknownFields(const nlohmann::json& object, std::initializer_list<std::string_view> allowed,
                         const std::string& path);

/// object[key]; throws "PATH: missing field 'key'" when absent. `object` must be an object.
[[nodiscard]] const nlohmann::json& requiredField(const nlohmann::json& object, std::string_view key,
                                                  const std::string& path);
/// object[key], or nullptr when absent (or null).
[[nodiscard]] const nlohmann::json* optionalField(const nlohmann::json& object, std::string_view key);

/// A finite number (integers accepted).
[[nodiscard]] double finiteNumber(const nlohmann::json& value, const std::string& path);
/// An integer in [low, high] (a number with a fraction is refused).
[[nodiscard]] std::int64_t integerInRange(const nlohmann::json& value, std::int64_t low, std::int64_t high,
                                          const std::string& path);
[[nodiscard]] std::string stringValue(const nlohmann::json& value, const std::string& path);
/// [x, y, z] of finite numbers.
[[nodiscard]] glm::dvec3 dvec3Value(const nlohmann::json& value, const std::string& path);
/// [x, y, z] as JSON numbers; doubles are written with round-trip precision.
[[nodiscard]] nlohmann::json dvec3Json(const glm::dvec3& v);

/// Line and column (1-based) of byte offset `offset` in `text`.
struct TextPosition {
    std::size_t line = 1;
    std::size_t column = 1;
};
[[nodiscard]] TextPosition textPosition(std::string_view text, std::size_t offset);

/// The text is not a JSON document. `truncated` is true when it ends in the middle of one
/// (the usual sign of a partly written or cut-off file); `reason` is what is wrong.
class JsonSyntaxError : public std::runtime_error {
public:
    JsonSyntaxError(TextPosition position, bool truncated, std::string reason);
    [[nodiscard]] TextPosition position() const noexcept { return m_position; }
    [[nodiscard]] bool truncated() const noexcept { return m_truncated; }
    [[nodiscard]] const std::string& reason() const noexcept { return m_reason; }

private:
    TextPosition m_position;
    bool m_truncated = false;
    std::string m_reason;
};

/// Parses `text` as one JSON document. Throws JsonSyntaxError for invalid or truncated
/// JSON and for arrays/objects nested deeper than `maxDepth` (which could exhaust the
/// stack of recursive consumers).
[[nodiscard]] nlohmann::json parseJsonText(std::string_view text, std::size_t maxDepth = 64);

/// "invalid JSON at line L, column C: REASON" ("truncated JSON at …" when it ended early).
[[nodiscard]] std::string jsonSyntaxErrorText(const JsonSyntaxError& error);

/// A whole JSON document format's parse: parseJsonText, then `read(document)`; a syntax
/// error becomes `Error(displayName, "", jsonSyntaxErrorText(…))` and a JsonPathError
/// `Error(displayName, path, reason)` — `Error` being the format's DocumentFileError.
template <class Error, class Read>
auto readJsonDocument(std::string_view text, const std::string& displayName, Read&& read)
{
    nlohmann::json document;
    try {
        document = parseJsonText(text);
    } catch (const JsonSyntaxError& error) {
        throw Error(displayName, "", jsonSyntaxErrorText(error));
    }
    try {
        return read(std::as_const(document));
    } catch (const JsonPathError& error) {
        throw Error(displayName, error.path(), error.reason());
    }
}

} // namespace trimlab::io
