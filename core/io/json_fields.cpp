#include "core/io/json_fields.h"

#include "core/io/json_nesting.h"

#include <algorithm>
#include <cmath>

namespace trimlab::io {

JsonPathError::JsonPathError(std::string path, std::string reason)
    : std::runtime_error(path.empty() ? reason : path + ": " + reason),
      m_path(std::move(path)),
      m_reason(std::move(reason))
{
}

std::string fieldPath(const std::string& parent, std::string_view key)
{
    return parent.empty() ? std::string(key) : parent + "." + std::string(key);
}

std::string indexPath(const std::string& parent, std::size_t index)
{
    return parent + "[" + std::to_string(index) + "]";
}

std::string jsonTypeText(const nlohmann::json& value)
{
    switch (value.type()) {
    case nlohmann::json::value_t::null:
        return "null";
    case nlohmann::json::value_t::object:
        return "an object";
    case nlohmann::json::value_t::array:
        return "an array";
    case nlohmann::json::value_t::string:
        return "a string";
    case nlohmann::json::value_t::boolean:
        return "a boolean";
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
        return "an integer";
    case nlohmann::json::value_t::number_float:
        return "a number";
    default:
        return "binary data";
    }
}

void requireObject(const nlohmann::json& value, const std::string& path)
{
    if (!value.is_object())
        throw JsonPathError(path, "must be an object, not " + jsonTypeText(value));
}

void requireArray(const nlohmann::json& value, const std::string& path)
{
    if (!value.is_array())
        throw JsonPathError(path, "must be an array, not " + jsonTypeText(value));
}

void rejectUnknownFields(const nlohmann::json& object, std::initializer_list<std::string_view> allowed,
                         const std::string& path)
{
    for (const auto& item : object.items()) {
        if (std::find(allowed.begin(), allowed.end(), std::string_view(item.key())) == allowed.end()) {
            std::string known;
            for (const std::string_view name : allowed)
                known += (known.empty() ? "" : ", ") + std::string(name);
            throw JsonPathError(fieldPath(path, item.key()), "unknown field (known fields: " + known + ")");
        }
    }
}

const nlohmann::json& requiredField(const nlohmann::json& object, std::string_view key, const std::string& path)
{
    const auto it = object.find(key);
    if (it == object.end())
        throw JsonPathError(path, "missing field '" + std::string(key) + "'");
    return *it;
}

const nlohmann::json* optionalField(const nlohmann::json& object, std::string_view key)
{
    const auto it = object.find(key);
    return it == object.end() || it->is_null() ? nullptr : &*it;
}

double finiteNumber(const nlohmann::json& value, const std::string& path)
{
    if (!value.is_number())
        throw JsonPathError(path, "must be a number, not " + jsonTypeText(value));
    const double number = value.get<double>();
    if (!std::isfinite(number))
        throw JsonPathError(path, "must be finite");
    return number;
}

std::int64_t integerInRange(const nlohmann::json& value, std::int64_t low, std::int64_t high, const std::string& path)
{
    const std::string range = " in [" + std::to_string(low) + ", " + std::to_string(high) + "]";
    if (value.is_number_unsigned()) {
        const auto u = value.get<std::uint64_t>();
        if (u > static_cast<std::uint64_t>(high) || (low > 0 && u < static_cast<std::uint64_t>(low)))
            throw JsonPathError(path, "must be an integer" + range + ", not " + std::to_string(u));
        return static_cast<std::int64_t>(u);
    }
    if (!value.is_number_integer())
        throw JsonPathError(path, "must be an integer" + range + ", not " + jsonTypeText(value));
    const auto i = value.get<std::int64_t>();
    if (i < low || i > high)
        throw JsonPathError(path, "must be an integer" + range + ", not " + std::to_string(i));
    return i;
}

std::string stringValue(const nlohmann::json& value, const std::string& path)
{
    if (!value.is_string())
        throw JsonPathError(path, "must be a string, not " + jsonTypeText(value));
    return value.get<std::string>();
}

glm::dvec3 dvec3Value(const nlohmann::json& value, const std::string& path)
{
    if (!value.is_array() || value.size() != 3)
        throw JsonPathError(path, "must be an array of 3 numbers [x, y, z]");
    return {finiteNumber(value[0], indexPath(path, 0)), finiteNumber(value[1], indexPath(path, 1)),
            finiteNumber(value[2], indexPath(path, 2))};
}

nlohmann::json dvec3Json(const glm::dvec3& v)
{
    return nlohmann::json::array({v.x, v.y, v.z});
}

TextPosition textPosition(std::string_view text, std::size_t offset)
{
    TextPosition position;
    const std::size_t end = std::min(offset, text.size());
    for (std::size_t i = 0; i < end; ++i) {
        if (text[i] == '\n') {
            ++position.line;
            position.column = 1;
        } else {
            ++position.column;
        }
    }
    return position;
}

JsonSyntaxError::JsonSyntaxError(TextPosition position, bool truncated, std::string reason)
    : std::runtime_error(reason), m_position(position), m_truncated(truncated), m_reason(std::move(reason))
{
}

namespace {

// nlohmann's message without its "[json.exception...] parse error at line L, column C: "
// prefix (we report the position ourselves).
std::string parseReason(const std::string& message)
{
    const std::size_t colon = message.find(": ", message.find("parse error"));
    return colon == std::string::npos ? message : message.substr(colon + 2);
}

// nlohmann refuses a number beyond the double range ("1e999") with out_of_range 406
// ("number overflow parsing '1e999'"), which carries no position: find the number.
JsonSyntaxError numberOverflow(std::string_view text, const std::string& message)
{
    const std::size_t open = message.find('\'');
    const std::size_t close = open == std::string::npos ? open : message.find('\'', open + 1);
    if (close == std::string::npos)
        return JsonSyntaxError(TextPosition{}, false, message);
    const std::string number = message.substr(open + 1, close - open - 1);
    const std::size_t offset = text.find(number);
    return JsonSyntaxError(offset == std::string_view::npos ? TextPosition{} : textPosition(text, offset), false,
                           "the number " + number + " does not fit a double; use finite values");
}

} // namespace

nlohmann::json parseJsonText(std::string_view text, std::size_t maxDepth)
{
    if (const std::size_t deep = jsonTooDeepAt(text, maxDepth); deep != std::string_view::npos)
        throw JsonSyntaxError(textPosition(text, deep), false,
                              "arrays and objects are nested deeper than " + std::to_string(maxDepth) + " levels");
    try {
        return nlohmann::json::parse(text.begin(), text.end());
    } catch (const nlohmann::json::parse_error& error) {
        // error.byte is the 1-based index of the character where parsing stopped; past
        // the end means the document stopped in the middle.
        const bool blank = text.find_first_not_of(" \t\r\n") == std::string_view::npos;
        if (blank)
            throw JsonSyntaxError(TextPosition{}, false, "the document is empty");
        const bool truncated = error.byte > text.size();
        const std::size_t offset = error.byte > 0 ? std::min<std::size_t>(error.byte - 1, text.size()) : 0;
        throw JsonSyntaxError(textPosition(text, offset), truncated, parseReason(error.what()));
    } catch (const nlohmann::json::out_of_range& error) {
        throw numberOverflow(text, error.what());
    }
}

std::string jsonSyntaxErrorText(const JsonSyntaxError& error)
{
    return std::string(error.truncated() ? "truncated JSON at " : "invalid JSON at ") + "line " +
           std::to_string(error.position().line) + ", column " + std::to_string(error.position().column) + ": " +
           error.reason();
}

} // namespace trimlab::io
