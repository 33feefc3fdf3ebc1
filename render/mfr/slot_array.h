#pragma once
/// \file
/// k fixed fragment slots per pixel: the thesis's "3D array buffer" of the k⁺-buffer and
/// AB_FP, an RG32UI 2D array texture with one layer per slot (fragment_pack.glsl's
/// format), bound at binding::kFragmentsImage. A layered texture is not bound by the
/// driver's shader-storage block limit (128 MB on llvmpipe).

#include "render/gl/gl_functions.h"
#include "render/gl/gl_objects.h"

#include <cstddef>

namespace trimlab::render {

class SlotArray {
public:
    explicit SlotArray(GlFunctions& gl);

    /// (Re)allocates width×height×k slots; no-op when unchanged. Throws
    /// std::invalid_argument for k outside 1..MethodParameters::kMaxK and GpuMemoryError
    /// (naming `owner`, e.g. "k+-buffer") when the GPU cannot hold them.
    void allocate(int width, int height, int k, const char* owner);
    /// Binds the slots for shader read/write.
    void bind();

    [[nodiscard]] int k() const { return m_k; }
    /// Bytes of the slots alone.
    [[nodiscard]] std::size_t bytes() const { return slotBytes(m_width, m_height, m_k); }
    [[nodiscard]] static std::size_t slotBytes(int width, int height, int k);

private:
    GlFunctions& m_gl;
    GlTexture m_texture;
    int m_width = 0;
    int m_height = 0;
    int m_k = 0;
};

} // namespace trimlab::render
