#pragma once
/// \file
/// The framebuffer every trim render draws into: an RGBA8 color image, an RGBA32UI id
/// image (encoding in shaders/common/trim_output.glsl) and a depth buffer. The viewport
/// blits its color to the window; tests and exports read both back.

#include "render/gl/gl_functions.h"
#include "render/gl/gl_objects.h"

#include "core/trim/trim_image.h"

#include <QImage>

namespace trimlab::render {

class RenderTarget {
public:
    explicit RenderTarget(GlFunctions& gl);

    /// (Re)allocates the attachments when the size changes. Throws GpuMemoryError.
    void resize(int width, int height);
    [[nodiscard]] int width() const { return m_width; }
    [[nodiscard]] int height() const { return m_height; }
    [[nodiscard]] GLuint framebuffer() const { return m_framebuffer.id(); }
    [[nodiscard]] std::size_t memoryBytes() const;

    /// Binds the framebuffer with both color attachments as draw buffers.
    void bindForDrawing();
    /// Draws one triangle covering the viewport (shaders/fullscreen.vert) with the current
    /// program; no vertex buffer needed.
    void drawFullscreenTriangle();
    /// Copies the color image into `framebuffer` (0 = the default one) at the same size.
    void blitColorTo(GLuint framebuffer);

    /// The color image, row 0 at the top (waits for the GPU).
    [[nodiscard]] QImage readColor();
    /// The id image decoded into per-pixel answers, row 0 at the top (waits for the GPU).
    [[nodiscard]] TrimImage readTrimImage();

private:
    GlFunctions& m_gl;
    GlFramebuffer m_framebuffer;
    GlTexture m_color;
    GlTexture m_info;
    GlTexture m_depth;
    GlVertexArray m_emptyVao; // core profile: a draw needs a bound vertex array
    int m_width = 0;
    int m_height = 0;
};

} // namespace trimlab::render
