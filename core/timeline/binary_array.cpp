#include "core/timeline/binary_array.h"

#include "core/timeline/base64.h"
#include "core/io/json_fields.h"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <limits>

namespace trimlab::timeline {

using io::fieldPath;
using io::integerInRange;
using io::JsonPathError;
using io::requiredField;
using io::requireObject;
using io::stringValue;

namespace {

std::uint32_t crc32Of(std::span<const std::uint8_t> bytes)
{
    uLong crc = crc32(0L, Z_NULL, 0);
    // zlib takes uInt lengths; feed large payloads in pieces.
    std::size_t offset = 0;
    while (offset < bytes.size()) {
        const std::size_t piece = std::min<std::size_t>(bytes.size() - offset, std::numeric_limits<uInt>::max());
        crc = crc32(crc, bytes.data() + offset, static_cast<uInt>(piece));
        offset += piece;
    }
    return static_cast<std::uint32_t>(crc);
}

std::string hex(std::uint32_t value)
{
    char text[16];
    std::snprintf(text, sizeof text, "0x%08x", value);
    return text;
}

nlohmann::json arrayJson(std::string_view type, std::span<const std::uint32_t> words, std::size_t wordsPerValue = 1)
{
    std::vector<std::uint8_t> bytes;
    bytes.reserve(words.size() * 4);
    for (const std::uint32_t w : words) {
        for (int shift = 0; shift < 32; shift += 8)
            bytes.push_back(std::uint8_t((w >> shift) & 0xff)); // little-endian on every host
    }
    return nlohmann::json{{"type", type},
                          {"count", words.size() / wordsPerValue},
                          {"crc32", crc32Of(bytes)},
                          {"base64", base64Encode(bytes)}};
}

// `wordsPerValue` 32-bit words per stored value (2 for float64): `count` counts values.
std::vector<std::uint32_t> readWords(const nlohmann::json& value, std::string_view type, const std::string& path,
                                     std::size_t wordsPerValue = 1)
{
    requireObject(value, path);
    const std::string actualType = stringValue(requiredField(value, "type", path), fieldPath(path, "type"));
    if (actualType != type)
        throw JsonPathError(fieldPath(path, "type"),
                            "must be \"" + std::string(type) + "\", not \"" + actualType + "\"");
    const auto count = std::size_t(integerInRange(
        requiredField(value, "count", path), 0,
        std::numeric_limits<std::int64_t>::max() / std::int64_t(4 * wordsPerValue), fieldPath(path, "count")));
    const std::size_t byteCount = count * 4 * wordsPerValue;
    const auto storedCrc =
        std::uint32_t(integerInRange(requiredField(value, "crc32", path), 0, 0xffffffffLL, fieldPath(path, "crc32")));
    const std::string text = stringValue(requiredField(value, "base64", path), fieldPath(path, "base64"));
    std::vector<std::uint8_t> bytes;
    try {
        bytes = base64Decode(text);
    } catch (const std::invalid_argument& error) {
        throw JsonPathError(fieldPath(path, "base64"), std::string("damaged base64: ") + error.what());
    }
    if (bytes.size() != byteCount)
        throw JsonPathError(path, "holds " + std::to_string(bytes.size()) + " bytes, but count " +
                                      std::to_string(count) + " needs " + std::to_string(byteCount));
    const std::uint32_t actualCrc = crc32Of(bytes);
    if (actualCrc != storedCrc)
        throw JsonPathError(path, "CRC mismatch: stored " + hex(storedCrc) + ", data " + hex(actualCrc) +
                                      " (the file is damaged)");
    std::vector<std::uint32_t> words(byteCount / 4);
    for (std::size_t i = 0; i < words.size(); ++i) {
        const std::uint8_t* b = bytes.data() + 4 * i;
        words[i] = std::uint32_t(b[0]) | (std::uint32_t(b[1]) << 8) | (std::uint32_t(b[2]) << 16) |
                   (std::uint32_t(b[3]) << 24);
    }
    return words;
}

} // namespace

nlohmann::json floatArrayJson(std::span<const float> values)
{
    std::vector<std::uint32_t> words(values.size());
    for (std::size_t i = 0; i < values.size(); ++i)
        words[i] = std::bit_cast<std::uint32_t>(values[i]);
    return arrayJson("float32", words);
}

nlohmann::json uint32ArrayJson(std::span<const std::uint32_t> values)
{
    return arrayJson("uint32", values);
}

nlohmann::json positionArrayJson(std::span<const glm::vec3> positions)
{
    std::vector<float> values;
    values.reserve(positions.size() * 3);
    for (const glm::vec3& p : positions)
        values.insert(values.end(), {p.x, p.y, p.z});
    return floatArrayJson(values);
}

nlohmann::json doubleArrayJson(std::span<const double> values)
{
    // Low word first: the 8 bytes of each double are little-endian, like the 4-byte types.
    std::vector<std::uint32_t> words;
    words.reserve(values.size() * 2);
    for (const double v : values) {
        const auto bits = std::bit_cast<std::uint64_t>(v);
        words.push_back(std::uint32_t(bits & 0xffffffffu));
        words.push_back(std::uint32_t(bits >> 32));
    }
    return arrayJson("float64", words, 2);
}

nlohmann::json dvec3ArrayJson(std::span<const glm::dvec3> points)
{
    std::vector<double> values;
    values.reserve(points.size() * 3);
    for (const glm::dvec3& p : points)
        values.insert(values.end(), {p.x, p.y, p.z});
    return doubleArrayJson(values);
}

std::vector<double> readDoubleArray(const nlohmann::json& value, const std::string& path)
{
    const std::vector<std::uint32_t> words = readWords(value, "float64", path, 2);
    std::vector<double> values(words.size() / 2);
    for (std::size_t i = 0; i < values.size(); ++i)
        values[i] = std::bit_cast<double>(std::uint64_t(words[2 * i]) | (std::uint64_t(words[2 * i + 1]) << 32));
    return values;
}

std::vector<glm::dvec3> readDvec3Array(const nlohmann::json& value, const std::string& path)
{
    const std::vector<double> values = readDoubleArray(value, path);
    if (values.size() % 3 != 0)
        throw JsonPathError(fieldPath(path, "count"),
                            "must be a multiple of 3 for points, not " + std::to_string(values.size()));
    std::vector<glm::dvec3> points(values.size() / 3);
    for (std::size_t i = 0; i < points.size(); ++i)
        points[i] = {values[3 * i], values[3 * i + 1], values[3 * i + 2]};
    return points;
}

std::vector<float> readFloatArray(const nlohmann::json& value, const std::string& path)
{
    const std::vector<std::uint32_t> words = readWords(value, "float32", path);
    std::vector<float> values(words.size());
    for (std::size_t i = 0; i < words.size(); ++i)
        values[i] = std::bit_cast<float>(words[i]);
    return values;
}

std::vector<std::uint32_t> readUint32Array(const nlohmann::json& value, const std::string& path)
{
    return readWords(value, "uint32", path);
}

std::vector<glm::vec3> readPositionArray(const nlohmann::json& value, const std::string& path)
{
    const std::vector<float> values = readFloatArray(value, path);
    if (values.size() % 3 != 0)
        throw JsonPathError(fieldPath(path, "count"),
                            "must be a multiple of 3 for positions, not " + std::to_string(values.size()));
    std::vector<glm::vec3> positions(values.size() / 3);
    for (std::size_t i = 0; i < positions.size(); ++i)
        positions[i] = {values[3 * i], values[3 * i + 1], values[3 * i + 2]};
    return positions;
}

} // namespace trimlab::timeline
