#pragma once
/// \file
/// The per-pixel state the depth-peeling methods (F2B, DUAL) carry between their passes:
/// - PixelState: the exact winding index at the span start, the fragments peeled so far
///   (its counter, which readOccupancy reports) and the unresolved flag;
/// - the peeling cursor, an R32UI array at IMAGE_PEEL_DEPTH, one field per layer
///   (F2B: 7 layers, DUAL: 14; shaders/common/peel_state.glsl documents them);
/// - the trim walks, an RGBA32UI array at IMAGE_WALK (F2B: the walk from the front;
///   DUAL: also the walk from the back).
/// A fixed number of bytes per pixel, whatever the scene.

#include "render/gl/gl_functions.h"
#include "render/gl/gl_objects.h"
#include "render/mfr/pixel_state.h"

#include <cstddef>

namespace trimlab::render {

class ShaderLibrary;

class PeelingState {
public:
    /// `dual`: also the back cursor and the back walk (dual depth peeling).
    PeelingState(GlFunctions& gl, bool dual);

    /// (Re)allocates for width×height; no-op when unchanged. Throws GpuMemoryError.
    void allocate(int width, int height);
    /// Puts every pixel back to "nothing counted, nothing peeled" (two compute passes).
    void clear(ShaderLibrary& shaders);
    /// Binds the PixelState images and both arrays for shader read/write.
    void bind();

    /// Fragments peeled per pixel and the unresolved flags of the last frame.
    [[nodiscard]] PixelOccupancy readOccupancy() { return m_pixels.readOccupancy(); }
    [[nodiscard]] std::size_t memoryBytes() const;
    [[nodiscard]] static std::size_t bytesPerPixel(bool dual);

private:
    GlFunctions& m_gl;
    bool m_dual;
    PixelState m_pixels;
    GlTexture m_cursor;
    GlTexture m_walks;
    int m_width = 0;
    int m_height = 0;
};

} // namespace trimlab::render
