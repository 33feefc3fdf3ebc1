#pragma once
/// \file
/// The per-pixel head image of the node-buffer methods (an R32UI image at
/// binding::kHeadImage): the first node of a pixel's region (S-buffer, K⁺B-SB) or the
/// head of its linked list (AB_LL, node index + 1, 0 = empty).

#include "render/gl/gl_functions.h"
#include "render/gl/gl_objects.h"

#include <cstddef>

namespace trimlab::render {

class ShaderLibrary;

class HeadImage {
public:
    explicit HeadImage(GlFunctions& gl);

    /// (Re)allocates for width×height; no-op when unchanged. Throws GpuMemoryError.
    void allocate(int width, int height);
    /// Sets every head to 0 (the empty list; shaders/head_clear.comp).
    void clear(ShaderLibrary& shaders);
    /// Binds the image for shader read/write.
    void bind();

    [[nodiscard]] std::size_t memoryBytes() const { return std::size_t(m_width) * std::size_t(m_height) * 4; }

private:
    GlFunctions& m_gl;
    GlTexture m_texture;
    int m_width = 0;
    int m_height = 0;
};

} // namespace trimlab::render
