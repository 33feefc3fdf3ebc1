#pragma once
/// \file
/// The rules every format reader enforces, and their wording, so that all formats report
/// the same problem the same way: coordinates must be finite floats, declared counts
/// never drive an allocation larger than the data could fill, text formats contain no
/// binary data.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace trimlab {

/// Largest vertex count a loaded mesh may have: indices are 32-bit.
inline constexpr std::uint64_t kMaxMeshVertices = 0xFFFFFFFFull;

/// How many items to `reserve` for `declared` items when each needs at least
/// `minBytesPerItem` (> 0) of the `bytesRemaining`: never more than the data could hold,
/// so a lying header cannot trigger a huge allocation.
[[nodiscard]] std::size_t cappedReserve(std::uint64_t declared, std::size_t bytesRemaining,
                                        std::size_t minBytesPerItem);

/// True if `value` is finite and fits in a float (|value| <= FLT_MAX).
[[nodiscard]] bool isFiniteFloat(double value);

/// "nan", "inf", "-inf", or "1e+300 (too large for a 32-bit float)": why `value` failed
/// isFiniteFloat.
[[nodiscard]] std::string describeNonFinite(double value);

/// "has a non-finite coordinate (nan); coordinates must be finite numbers".
[[nodiscard]] std::string nonFiniteCoordinateReason(double value);

/// "the file has only 8 vertices" / "the file has no vertices", plus " (numbered 0 to 7)"
/// when `zeroBased`.
[[nodiscard]] std::string vertexCountPhrase(std::size_t vertexCount, bool zeroBased);

/// "8 vertices", "1 vertex": a count with the noun in singular or plural.
[[nodiscard]] std::string countNoun(std::uint64_t count, std::string_view singular, std::string_view plural);

/// Throws MeshLoadError if `text` holds a NUL byte: binary data in a text format
/// ("is this really a FORMAT file?").
void rejectBinaryData(std::string_view text, const std::string& displayName, std::string_view formatName);

} // namespace trimlab
