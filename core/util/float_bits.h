#pragma once
/// \file
/// Bit-pattern equality of positions. The timeline promises bit-exact history, so it
/// compares floats by their bits: -0.0f differs from 0.0f and a NaN equals itself.

#include <glm/vec3.hpp>

#include <bit>
#include <cstdint>

namespace trimlab {

/// True when every component of `a` has the same 32-bit pattern as in `b`.
[[nodiscard]] inline bool sameBits(const glm::vec3& a, const glm::vec3& b)
{
    return std::bit_cast<std::uint32_t>(a.x) == std::bit_cast<std::uint32_t>(b.x) &&
           std::bit_cast<std::uint32_t>(a.y) == std::bit_cast<std::uint32_t>(b.y) &&
           std::bit_cast<std::uint32_t>(a.z) == std::bit_cast<std::uint32_t>(b.z);
}

/// The same for double-precision points (control points of editable surfaces).
[[nodiscard]] inline bool sameBits(const glm::dvec3& a, const glm::dvec3& b)
{
    return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
           std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y) &&
           std::bit_cast<std::uint64_t>(a.z) == std::bit_cast<std::uint64_t>(b.z);
}

} // namespace trimlab
