#pragma once
/// \file
/// The names of a save's temporary files, and clearing away what killed saves leave
/// behind. writeFileAtomically writes `<name>.tmp-XXXXXX` (6 characters of [a-z0-9]) next
/// to `<name>` and renames it over `<name>`; a process killed between the two leaves the
/// temporary file, while `<name>` itself stays intact (core.save_kill). Such files are
/// never read by TrimLab. A name so long that the temporary's would not fit the folder's
/// file-name limit is shortened, with a hash of the whole name kept so that two long names
/// never share temporaries.

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace trimlab::io {

/// The part of a temporary's name before its 6 random characters: `<target name>.tmp-`,
/// or, when that and the 6 characters would exceed `nameLimit` bytes, the target name cut
/// at a character boundary, `~`, 8 hex digits of its hash and `.tmp-`.
[[nodiscard]] std::string temporaryPrefix(const std::filesystem::path& target, std::size_t nameLimit);

/// The number of random characters after temporaryPrefix.
inline constexpr std::size_t kTemporarySuffixLength = 6;

/// True for the file name of a temporary that writeFileAtomically made for `target`
/// (same folder assumed): exactly temporaryPrefix(target, the folder's limit) followed by
/// 6 of [a-z0-9].
[[nodiscard]] bool isAtomicWriteTemporaryOf(const std::filesystem::path& target,
                                            const std::filesystem::path& candidate);

/// Deletes the temporaries of `target` that were last modified at least `minimumAge`
/// ago and returns their paths. The age keeps a save that another process is running
/// right now (seconds at most) from losing its file. Best effort: a folder or file that
/// cannot be listed or removed is skipped, never reported as an error (the save that
/// calls this has already succeeded).
std::vector<std::filesystem::path> removeStaleTemporaries(const std::filesystem::path& target,
                                                          std::chrono::seconds minimumAge);

/// The age after which writeFileAtomically deletes a temporary of the file it writes:
/// far longer than any save takes, so it only ever removes leftovers of killed saves.
inline constexpr std::chrono::seconds kStaleTemporaryAge{600};

} // namespace trimlab::io
