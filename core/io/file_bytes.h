#pragma once
/// \file
/// Reading a whole (small enough) file into memory, with reasons fit for a user.

#include <cstddef>
#include <filesystem>
#include <string>

namespace trimlab::timeline {

/// The bytes of `path`. Throws std::runtime_error whose what() is only the reason
/// ("cannot open: No such file or directory", "is not a regular file", "is larger than
/// 4294967296 bytes", "read error: ..."); the caller adds the file name.
[[nodiscard]] std::string readFileBytes(const std::filesystem::path& path, std::size_t maxBytes);

} // namespace trimlab::timeline
