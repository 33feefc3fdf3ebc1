#pragma once
/// \file
/// The binary arrays of a project file: a JSON object
/// `{"type": "float32"|"uint32"|"float64", "count": N, "crc32": C, "base64": "..."}`
/// holding N little-endian 4-byte values (8-byte for float64, format version 2),
/// base64-encoded, with the zlib CRC-32 of the raw bytes.
/// Floats travel as their bit patterns, so -0.0f, denormals and every rounding survive a
/// round trip exactly. Internal to core/timeline.

#include <nlohmann/json.hpp>

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace trimlab::timeline {

[[nodiscard]] nlohmann::json floatArrayJson(std::span<const float> values);
[[nodiscard]] nlohmann::json uint32ArrayJson(std::span<const std::uint32_t> values);
/// #n×3 floats, x y z per position.
[[nodiscard]] nlohmann::json positionArrayJson(std::span<const glm::vec3> positions);
/// float64 arrays: doubles as their bit patterns (control points of editable surfaces).
[[nodiscard]] nlohmann::json doubleArrayJson(std::span<const double> values);
/// #n×3 doubles, x y z per point.
[[nodiscard]] nlohmann::json dvec3ArrayJson(std::span<const glm::dvec3> points);

/// Decode the array object at `path`. Throw JsonPathError for a wrong shape or type, bad
/// base64, a byte length that disagrees with `count`, or a CRC mismatch ("CRC mismatch:
/// stored 0x1234abcd, data 0x89ab0123").
[[nodiscard]] std::vector<float> readFloatArray(const nlohmann::json& value, const std::string& path);
[[nodiscard]] std::vector<std::uint32_t> readUint32Array(const nlohmann::json& value, const std::string& path);
[[nodiscard]] std::vector<double> readDoubleArray(const nlohmann::json& value, const std::string& path);
/// A float64 array whose count must be a multiple of 3, as points.
[[nodiscard]] std::vector<glm::dvec3> readDvec3Array(const nlohmann::json& value, const std::string& path);
/// A float array whose count must be a multiple of 3, as positions.
[[nodiscard]] std::vector<glm::vec3> readPositionArray(const nlohmann::json& value, const std::string& path);

} // namespace trimlab::timeline
