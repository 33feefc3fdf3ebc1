#pragma once
/// \file
/// Typed failures of the OpenGL layer. Each message names what failed and what the user
/// can do about it; the UI shows it in a dialog, batch verbs print it and exit non-zero.

#include <stdexcept>
#include <string>

namespace trimlab::render {

/// Base of every render-layer error.
class GlError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// No usable OpenGL 4.3 core context, or a required feature is missing.
class GlUnavailableError : public GlError {
public:
    using GlError::GlError;
};

/// A shader failed to compile or link; the message holds the info log and the numbered
/// source around the reported lines.
class ShaderBuildError : public GlError {
public:
    using GlError::GlError;
};

/// A buffer or image could not be allocated (GL_OUT_OF_MEMORY or above a driver limit).
class GpuMemoryError : public GlError {
public:
    using GlError::GlError;
};

/// "12.3 MB" (MiB, one decimal), as GpuMemoryError messages give sizes.
[[nodiscard]] std::string megabytesText(double bytes);

} // namespace trimlab::render
