#pragma once
/// \file
/// The skeleton as a JSON file (docs/skeleton.md): the rig's joints ("nodes"), its tree
/// ("root", "parent", "edges"), its bones and the vertex → joint mapping, optionally with
/// the curve skeleton it was selected from. Written by `trimlab skeleton --json`, read
/// back with full validation so that a hand-edited file cannot produce an inconsistent
/// rig.
///
///     {
///       "format": "trimlab-skeleton", "version": 1,
///       "nodes": [[x, y, z], ...],                       // #J joint positions (mesh units)
///       "root": 0,                                       // root joint
///       "parent": [-1, 0, 1, ...],                       // #J parent joints, -1 at the root
///       "edges": [[head, tail], ...],                    // #J−1, bone order
///       "bones": [{"head": 0, "tail": 1, "parent_bone": -1}, ...],   // parents first
///       "vertex_joint": [0, 0, 3, ...],                  // #V, or [] when unknown
///       "curve_skeleton": {                              // optional
///         "nodes": [[x, y, z], ...], "edges": [[a, b], ...], "vertex_node": [...] }
///     }

#include "core/skeleton/skeleton.h"
#include "core/io/document_file_error.h"

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace trimlab {

inline constexpr std::string_view kSkeletonFormatName = "trimlab-skeleton";
inline constexpr int kSkeletonFormatVersion = 1;
/// Larger files are refused before parsing (a 1M-vertex mapping is about 8 MB).
inline constexpr std::size_t kMaxSkeletonFileBytes = std::size_t(1) << 30;

/// A skeleton file could not be read. `what()` reads `FILE: [WHERE: ]REASON`, with WHERE
/// a JSON path such as "bones[3].parent_bone" or "curve_skeleton.edges[7]", e.g.
/// `rig.json: bones[3].head: joint 5 is not the parent of tail 4`.
class SkeletonFileError : public io::DocumentFileError {
public:
    using DocumentFileError::DocumentFileError;
};

struct SkeletonDocument {
    SkeletonRig rig;
    std::optional<CurveSkeleton> curve;
};

/// The JSON text (ends with a newline). Doubles are written with round-trip precision,
/// so parsing gives back exactly `rig` and `curve`. Throws std::invalid_argument when the
/// rig is inconsistent (requireValidRig) or the curve skeleton names a node that does not
/// exist.
[[nodiscard]] std::string skeletonJson(const SkeletonRig& rig, const CurveSkeleton* curve = nullptr);

/// Writes skeletonJson atomically. Throws as skeletonJson, and std::runtime_error naming
/// the file when it cannot be written.
void saveSkeletonJson(const std::filesystem::path& path, const SkeletonRig& rig, const CurveSkeleton* curve = nullptr);

/// Parses and validates a skeleton document. Throws SkeletonFileError naming
/// `displayName` for invalid or truncated JSON (with line and column), a wrong format or
/// a newer version, a missing field, unknown fields, values of the wrong type, and every
/// inconsistency findRigProblem reports (with its JSON path), edges that differ from the
/// bones, and curve-skeleton indices out of range.
[[nodiscard]] SkeletonDocument parseSkeletonJson(std::string_view text, const std::string& displayName);

/// Reads `path` (at most kMaxSkeletonFileBytes) and parses it. Throws SkeletonFileError.
[[nodiscard]] SkeletonDocument loadSkeletonJson(const std::filesystem::path& path);

} // namespace trimlab
