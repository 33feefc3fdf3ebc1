#pragma once
/// \file
/// The per-pixel, per-object winding indices at the start of the kept span that CSG and
/// collision highlighting need (core/trim/trim_walk.h, "Per-object windings"; GLSL side:
/// shaders/common/object_windings.glsl): one shader storage buffer of `objects` ints per
/// pixel (the row length goes to the shaders as a uniform), counted by every geometry pass that counts
/// the summed index and read by the resolve. Objects 0 .. objects − 1 only, objects <=
/// kMaxCsgOperands (8): at 1024×768 and 8 objects it holds 24 MiB.

#include "render/gl/gl_functions.h"
#include "render/gl/gl_objects.h"

#include <cstddef>

namespace trimlab::render {

class ObjectWindingBuffer {
public:
    explicit ObjectWindingBuffer(GlFunctions& gl);

    /// (Re)allocates for width×height pixels and `objects` (1 .. kMaxCsgOperands) counts
    /// per pixel; no-op when unchanged. Throws GpuMemoryError when it does not fit and
    /// std::invalid_argument for an object count out of range.
    void allocate(int width, int height, int objects);
    /// Zeroes every count before a frame's counting pass.
    void clear();
    /// Binds the buffer at binding::kObjectWindingsStorage and gives `program` (in use)
    /// the row length.
    void bind(GLuint program);

    [[nodiscard]] int objects() const { return m_objects; }
    [[nodiscard]] std::size_t memoryBytes() const { return m_bytes; }
    [[nodiscard]] static std::size_t bytesFor(int width, int height, int objects);

private:
    GlFunctions& m_gl;
    GlBuffer m_buffer;
    int m_width = 0;
    int m_height = 0;
    int m_objects = 0;
    std::size_t m_bytes = 0;
};

} // namespace trimlab::render
