#pragma once
/// \file
/// Parsing a glTF 2.0 asset (JSON or GLB) into a tinygltf::Model, safely: the GLB header
/// and the JSON nesting are checked before tinygltf sees the data, images are never
/// decoded, and external files are read only where allowed. Internal to the glTF reader.

#include <tiny_gltf.h>

#include <filesystem>
#include <string>
#include <string_view>

namespace trimlab {

/// Parses `bytes` as binary glTF when it starts with "glTF", else as JSON glTF.
/// External buffers are read relative to `baseDir`; an empty `baseDir` refuses every
/// external file. Throws MeshLoadError naming `displayName` for: data that is neither
/// JSON nor GLB, a GLB with a wrong version or a truncated header, JSON nested more than
/// 256 levels (the parsers recurse), anything tinygltf rejects (its message is kept), and
/// required mesh-compression extensions (Draco, meshopt), which are not supported.
[[nodiscard]] tinygltf::Model parseGltfDocument(std::string_view bytes, const std::string& displayName,
                                                const std::filesystem::path& baseDir);

} // namespace trimlab
