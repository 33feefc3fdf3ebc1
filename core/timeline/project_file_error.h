#pragma once
/// \file
/// The typed exception project file loading throws: which file, where in it, and why.

#include "core/io/document_file_error.h"

namespace trimlab::timeline {

/// A .trimlab file could not be loaded. `what()` reads `FILE: [WHERE: ]REASON`, e.g.
/// `scene.trimlab: frames[3].after: CRC mismatch: stored 0x..., data 0x... (the file is
/// damaged)`, `scene.trimlab: truncated: the JSON document ends early (at byte 812 of
/// 812)` or `old.trimlab: version 7 is newer than this TrimLab (1)`. Thrown for every
/// problem caused by file contents or by reading the file; never for programmer errors.
class ProjectFileError : public io::DocumentFileError {
public:
    /// `where` is a JSON path such as "frames[3].after" or "" for the file as a whole.
    using DocumentFileError::DocumentFileError;
};

} // namespace trimlab::timeline
