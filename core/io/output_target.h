#pragma once
/// \file
/// The file an output path finally names, and whether TrimLab may replace it. An output
/// replaces only a regular file: a device, a FIFO, a socket or a folder at the path is
/// refused before any work (writing a render into /dev/sda or a FIFO another program
/// reads is never what a user meant). A symbolic link is followed and its final target is
/// written, the link itself kept: a user who links `latest.png` to a file in a shared
/// folder expects that file to change, as `cp` and every editor do. checkOutputPaths
/// (the verbs, before their work) and writeFileAtomically (every save) both ask here, so
/// the check and the write agree.

#include <filesystem>
#include <optional>
#include <string>

namespace trimlab::io {

/// The path's last component with its symbolic links followed, as the kernel would (at
/// most 40 links; a relative link target is taken from the link's own folder). The file
/// need not exist; a dangling link resolves to the file it would create. std::nullopt for
/// a link loop or a chain longer than 40.
[[nodiscard]] std::optional<std::filesystem::path> followOutputLinks(const std::filesystem::path& path);

/// What an existing non-regular file at `file` is ("a folder", "a FIFO (named pipe)",
/// "a socket", "a character device", "a block device"), or an empty string when `file`
/// is a regular file or does not exist. Does not follow a link at `file` itself.
[[nodiscard]] std::string nonRegularKind(const std::filesystem::path& file);

/// The resolved target of an output path, or a one-line reason why it cannot be written:
/// a link loop, a file name longer than its folder allows, or an existing file that is not
/// a regular one ("out.png is a FIFO (named pipe), not a regular file; give a file name").
struct OutputTarget {
    std::filesystem::path file;
    std::string problem;
};
[[nodiscard]] OutputTarget resolveOutputTarget(const std::filesystem::path& path);

/// The longest file name the folder accepts (pathconf's NAME_MAX; 255 when it cannot
/// tell).
[[nodiscard]] std::size_t fileNameLimit(const std::filesystem::path& folder);

} // namespace trimlab::io
