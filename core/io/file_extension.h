#pragma once
/// \file
/// The extension of a file name in lower case ("Mesh.GLB" -> ".glb"): every writer picks
/// its format by extension, in any case.

#include <filesystem>
#include <string>

namespace trimlab::io {

[[nodiscard]] std::string lowercaseExtension(const std::filesystem::path& path);

} // namespace trimlab::io
