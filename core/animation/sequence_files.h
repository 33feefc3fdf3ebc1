#pragma once
/// \file
/// Which files make up a mesh sequence: a folder, a printf-style numbered pattern or a
/// wildcard pattern, resolved to a list of files in natural order (natural_order.h).

#include <filesystem>
#include <string>
#include <vector>

namespace trimlab {

/// The files of the mesh sequence `spec`, in natural order of their file names:
/// - a folder: every file in it (not in subfolders) whose extension is .obj, .ply,
///   .off or .stl, each optionally followed by .gz; other files (README.txt, joint
///   tables) are ignored;
/// - a numbered pattern "dir/mesh_%04d.obj.gz" (or "%d"): the files of "dir" whose
///   names are the pattern with a run of digits in place of the conversion ("%0Nd"
///   requires at least N digits; "%%" is a literal percent sign);
/// - a wildcard pattern "dir/mesh_*.obj" with '*' (any run of characters) and '?' (one
///   character) in the file name part.
/// Wildcards or conversions in the folder part are not supported.
/// Throws MeshLoadError naming `spec` when the folder does not exist, nothing matches,
/// the pattern is malformed (e.g. "%s" or two conversions), or the files of a folder
/// have different formats ("… holds .obj and .ply files; name a pattern to choose").
[[nodiscard]] std::vector<std::filesystem::path> sequenceFiles(const std::string& spec);

/// True when `source` names a mesh sequence as sequenceFiles reads it: a folder, or a
/// pattern with '*', '?' or '%' in its file name (whether or not anything matches).
[[nodiscard]] bool isMeshSequenceSource(const std::string& source);

/// True when `source` names a glTF file (.gltf or .glb, optionally .gz; case-insensitive)
/// rather than a mesh sequence.
[[nodiscard]] bool isGltfSource(const std::string& source);

} // namespace trimlab
