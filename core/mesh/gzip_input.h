#pragma once
/// \file
/// In-memory gzip decompression for `.gz` mesh files (zlib).

#include <cstddef>
#include <string>
#include <string_view>

namespace trimlab {

/// True if `bytes` start with the gzip magic bytes 1f 8b.
[[nodiscard]] bool hasGzipMagic(std::string_view bytes);

/// Decompresses gzip data: one member or several concatenated ones (as `cat a.gz b.gz`
/// makes); zero bytes after the last member are ignored (padding).
/// Throws MeshLoadError naming `displayName` when the data is corrupt ("corrupt gzip
/// data"), truncated ("truncated gzip data"), followed by other bytes, or would
/// decompress to more than `maxOutputBytes` bytes — the output never grows beyond that
/// cap, so a small "zip bomb" cannot exhaust memory.
[[nodiscard]] std::string gunzip(std::string_view compressed, const std::string& displayName,
                                 std::size_t maxOutputBytes);

} // namespace trimlab
