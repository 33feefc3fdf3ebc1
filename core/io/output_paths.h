#pragma once
/// \file
/// The output files a run was asked for, checked before any work starts: a run that would
/// fail to write its last output after minutes of work, or write two outputs over one
/// another, fails at once instead and touches nothing. The files themselves are written
/// through a temporary file and a rename (atomic_write.h), so a failed or killed run
/// leaves every earlier file as it was.

#include <optional>
#include <string>
#include <vector>

namespace trimlab::io {

/// One requested output: the option that named it ("-o", "--depth") and the path given
/// (empty: not requested).
struct OutputRequest {
    std::string option;
    std::string path;
};

/// nullopt when every requested path can be written, else a one-line error naming the
/// option and the path: the path is a folder, a device, a FIFO or a socket, a link loop,
/// or a name too long for its folder (output_target.h); its folder does not exist, is not
/// a folder, or cannot be written into; or two options name the same file (after
/// following links and resolving ".", ".." and the folders' links). Never throws for any
/// text.
[[nodiscard]] std::optional<std::string> checkOutputPaths(const std::vector<OutputRequest>& outputs);

} // namespace trimlab::io
