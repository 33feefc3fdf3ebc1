#pragma once
/// \file
/// Reading a whole (small enough) file into memory, with reasons fit for a user. Only
/// regular files are read: a folder, a named pipe, a device, a socket or a loop of
/// symbolic links is refused up front, without blocking (a FIFO with no writer would
/// block a plain open; /dev/zero would never end), and no read goes past `maxBytes`.

#include <cstddef>
#include <filesystem>
#include <string>

namespace trimlab::io {

/// Why `path` is no regular file TrimLab may read ("No such file or directory", "is a
/// folder, not a regular file", the same for a named pipe (FIFO), a device, a socket or a
/// loop of symbolic links, ...), or "" when it is one. Symbolic links are followed.
[[nodiscard]] std::string regularFileProblem(const std::filesystem::path& path);

/// The bytes of `path`. Throws std::runtime_error whose what() is only the reason
/// ("cannot open: No such file or directory", "cannot open: is a named pipe (FIFO), not a
/// regular file", "is larger than 4294967296 bytes", "read error: ..."); the caller adds
/// the file name. The file is opened without blocking and checked again once open (it may
/// have been replaced after the first check); the size read is the size it had then.
[[nodiscard]] std::string readFileBytes(const std::filesystem::path& path, std::size_t maxBytes);

} // namespace trimlab::io
