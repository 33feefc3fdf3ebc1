#pragma once
/// \file
/// The per-pixel state most multi-fragment methods share: a fragment counter, a spin-lock
/// semaphore, the winding index at the span start and an overflow flag (four R32 images
/// at the units of gl/bindings.h), with the clear pass (shaders/pixel_state_clear.comp).

#include "render/gl/gl_functions.h"
#include "render/gl/gl_objects.h"

#include <cstdint>
#include <vector>

namespace trimlab::render {

class ShaderLibrary;

/// Per-pixel occupancy after a store pass, row 0 at the top: the fragments counted or
/// held per pixel and whether the pixel lost fragments. For diagnostics and tests.
struct PixelOccupancy {
    int width = 0;
    int height = 0;
    std::vector<std::uint32_t> held;
    std::vector<std::uint8_t> overflowed;
};

class PixelState {
public:
    explicit PixelState(GlFunctions& gl);

    /// (Re)allocates for width×height; no-op when unchanged. Throws GpuMemoryError.
    void allocate(int width, int height);
    /// Zeroes all four images (a compute pass) and makes the result visible to shaders.
    void clear(ShaderLibrary& shaders);
    /// Binds the four images for shader read/write.
    void bind();
    /// Reads the counter and overflow images back (waits for the GPU).
    [[nodiscard]] PixelOccupancy readOccupancy();

    [[nodiscard]] GLuint counterTexture() const { return m_counter.id(); }
    [[nodiscard]] std::size_t memoryBytes() const { return bytesFor(m_width, m_height); }
    [[nodiscard]] static std::size_t bytesFor(int width, int height);
    [[nodiscard]] int width() const { return m_width; }
    [[nodiscard]] int height() const { return m_height; }

private:
    GlFunctions& m_gl;
    GlTexture m_counter;
    GlTexture m_semaphore;
    GlTexture m_winding;
    GlTexture m_overflow;
    int m_width = 0;
    int m_height = 0;
};

/// A single-channel 32-bit image (`format` GL_RED_INTEGER) read back with row 0 at the top.
[[nodiscard]] std::vector<std::uint32_t> readImageTopDown(GlFunctions& gl, GLuint texture, int width, int height);

} // namespace trimlab::render
