#pragma once
/// \file
/// Replacing a file atomically: readers (and a crash) see either the old file or the
/// complete new one, never a mixture or a truncated file.

#include <filesystem>
#include <string_view>

namespace trimlab::io {

/// Writes `bytes` to `<path>.tmp-XXXXXX` in the same folder (created with mode 0666 minus
/// the umask), flushes and fsyncs it, then renames it over `path` and fsyncs the folder
/// (best effort). On any failure the temporary file is removed, `path` is left exactly
/// as it was, and std::runtime_error is thrown naming the file, the step and the system's
/// reason ("cannot write /a/b.trimlab: rename: Is a directory"). After a successful
/// rename, temporaries of `path` older than kStaleTemporaryAge (left by killed saves) are
/// deleted (stale_temporaries.h).
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

} // namespace trimlab::io
