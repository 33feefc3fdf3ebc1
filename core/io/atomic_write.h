#pragma once
/// \file
/// Replacing a file atomically: readers (and a crash) see either the old file or the
/// complete new one, never a mixture or a truncated file.

#include <filesystem>
#include <string_view>

namespace trimlab::io {

/// Writes `bytes` to `<path>.tmp-XXXXXX` in the same folder, flushes and fsyncs it, then
/// renames it over `path` and fsyncs the folder (best effort).
/// - `path` is resolved first (output_target.h): a symbolic link is followed and its
///   target written; a folder, device, FIFO or socket is refused before anything is
///   created.
/// - A new file gets mode 0666 minus the umask; a replaced file keeps its mode (a private
///   0600 file stays 0600).
/// - The temporary's name fits the folder's file-name limit however long `path`'s name is
///   (stale_temporaries.h).
/// - On any failure (a full disk, the file-size limit: the caller's process must ignore
///   SIGXFSZ to see it as an error) the temporary file is removed, `path` is left exactly
///   as it was, and std::runtime_error is thrown naming the file, the step and the
///   system's reason on one line ("cannot write /a/b.obj: write: File too large (the
///   file-size limit of this process, ulimit -f, was reached); the existing file is
///   unchanged").
/// After a successful rename, temporaries of `path` older than kStaleTemporaryAge (left
/// by killed saves) are deleted.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

} // namespace trimlab::io
