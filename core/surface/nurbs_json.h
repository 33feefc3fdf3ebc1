#pragma once
/// \file
/// NURBS surfaces as a JSON file (docs/nurbs-json.md): a list of surfaces, each with its
/// degrees, counts, knot vectors, control net and weights, written with round-trip
/// precision (loading gives back bit-identical doubles) and read back with full
/// validation, so a hand-edited file cannot produce a surface evaluation would trust.
///
///     {
///       "format": "trimlab-nurbs", "version": 1,
///       "surfaces": [{
///         "name": "sphere",
///         "degreeU": 2, "degreeV": 2, "countU": 9, "countV": 5,
///         "closedU": true, "closedV": false,
///         "knotsU": [0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4],    // countU+degreeU+1
///         "knotsV": [0, 0, 0, 1, 1, 2, 2, 2],                // countV+degreeV+1
///         "points": [[x, y, z], ...],                        // countU·countV, index j·countU+i
///         "weights": [1, 0.7071067811865476, ...]            // countU·countV, > 0
///       }]
///     }

#include "core/surface/nurbs_surface.h"

#include <filesystem>
#include <span>
#include "core/io/document_file_error.h"

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace trimlab {

inline constexpr std::string_view kNurbsFormatName = "trimlab-nurbs";
inline constexpr int kNurbsFormatVersion = 1;
/// Larger files are refused before parsing (1e6 control points take about 80 MB of text).
inline constexpr std::size_t kMaxNurbsFileBytes = std::size_t(256) << 20;
/// Most surfaces one file may hold.
inline constexpr std::size_t kMaxNurbsSurfacesPerFile = 1024;

/// A NURBS file could not be read. `what()` reads `FILE: [WHERE: ]REASON`, WHERE being a
/// JSON path such as "surfaces[0].knotsU[3]", e.g.
/// `hull.json: surfaces[0].knotsU[3]: knots must not decrease (0.5 after 0.75); sort the knot vector`.
class NurbsFileError : public io::DocumentFileError {
public:
    using DocumentFileError::DocumentFileError;
};

/// The JSON text of `surfaces` (ends with a newline). Throws std::invalid_argument when a
/// surface is invalid (requireValidNurbs) or there are more than kMaxNurbsSurfacesPerFile.
[[nodiscard]] std::string nurbsJson(std::span<const NurbsSurface> surfaces);

/// Writes nurbsJson atomically (io::writeFileAtomically). Throws as nurbsJson, and
/// std::runtime_error naming the file when it cannot be written.
void saveNurbsJson(const std::filesystem::path& path, std::span<const NurbsSurface> surfaces);

/// Parses and validates a NURBS document. Throws NurbsFileError naming `displayName` for
/// invalid or truncated JSON (line and column), a wrong format or newer version, missing
/// or unknown fields, wrong types, counts or degrees out of range, array sizes that do
/// not match the counts, NaN/Inf (not JSON, reported as invalid JSON) or out-of-range
/// numbers, non-positive weights, bad knot vectors, open seams of closed directions, and
/// more than kMaxNurbsControlPoints declared (checked before any array is read).
[[nodiscard]] std::vector<NurbsSurface> parseNurbsJson(std::string_view text, const std::string& displayName);

/// Reads `path` (at most kMaxNurbsFileBytes) and parses it. Throws NurbsFileError.
[[nodiscard]] std::vector<NurbsSurface> loadNurbsJson(const std::filesystem::path& path);

} // namespace trimlab
