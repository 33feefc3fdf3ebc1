// GLEW first: it must see GL before anything else includes gl.h (OpenCSG needs GLEW's
// function pointers, initialized by the application).
#include <GL/glew.h>

#include "opencsg_depth.h"

#include <glm/gtc/type_ptr.hpp>

#include <opencsg.h>

#include <algorithm>
#include <memory>

namespace trimlab::test {

namespace {

/// A solid drawn with immediate-mode vertices, as OpenCSG calls it (positions only).
class Solid final : public OpenCSG::Primitive {
public:
    Solid(const OpenCsgSolid& solid, OpenCSG::Operation operation)
        : OpenCSG::Primitive(operation, solid.convexity), m_corners(solid.corners)
    {
    }
    void render() override
    {
        glBegin(GL_TRIANGLES);
        for (const glm::dvec3& p : m_corners)
            glVertex3d(p.x, p.y, p.z);
        glEnd();
    }

private:
    const std::vector<glm::dvec3>& m_corners;
};

/// An RGBA8 + depth24/stencil8 framebuffer object, bound while alive.
class Framebuffer {
public:
    Framebuffer(int width, int height)
    {
        glGenFramebuffers(1, &m_framebuffer);
        glGenRenderbuffers(2, m_renderbuffers);
        glBindRenderbuffer(GL_RENDERBUFFER, m_renderbuffers[0]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
        glBindRenderbuffer(GL_RENDERBUFFER, m_renderbuffers[1]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
        glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_renderbuffers[0]);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, m_renderbuffers[1]);
        m_complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    }
    ~Framebuffer()
    {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteRenderbuffers(2, m_renderbuffers);
        glDeleteFramebuffers(1, &m_framebuffer);
    }
    Framebuffer(const Framebuffer&) = delete;
    Framebuffer& operator=(const Framebuffer&) = delete;
    [[nodiscard]] bool complete() const { return m_complete; }

private:
    GLuint m_framebuffer = 0;
    GLuint m_renderbuffers[2] = {0, 0};
    bool m_complete = false;
};

// The depth buffer, row 0 at the top.
std::vector<float> readDepth(int width, int height)
{
    std::vector<float> bottomUp(std::size_t(width) * std::size_t(height));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, bottomUp.data());
    std::vector<float> topDown(bottomUp.size());
    for (int y = 0; y < height; ++y)
        std::copy_n(&bottomUp[std::size_t(height - 1 - y) * std::size_t(width)], width,
                    &topDown[std::size_t(y) * std::size_t(width)]);
    return topDown;
}

} // namespace

std::vector<float> renderOpenCsgDepth(const std::vector<OpenCsgSolid>& solids,
                                      const std::vector<OpenCsgProduct>& products, const glm::dmat4& view,
                                      const glm::dmat4& projection, int width, int height, std::string* error)
{
    glewExperimental = GL_TRUE;
    if (const GLenum status = glewInit(); status != GLEW_OK) {
        if (error)
            *error = std::string("glewInit failed: ") + reinterpret_cast<const char*>(glewGetErrorString(status));
        return {};
    }
    Framebuffer framebuffer(width, height);
    if (!framebuffer.complete()) {
        if (error)
            *error = "the OpenCSG test framebuffer is incomplete";
        return {};
    }
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixd(glm::value_ptr(projection));
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixd(glm::value_ptr(view));
    OpenCSG::setOption(OpenCSG::AlgorithmSetting, OpenCSG::Goldfeather); // handles concave solids (a torus)
    OpenCSG::setOption(OpenCSG::OffscreenSetting, OpenCSG::FrameBufferObject);
    std::vector<float> depth(std::size_t(width) * std::size_t(height), 1.0f);
    // Every primitive lives until the end: OpenCSG keys internal state by primitive address.
    std::vector<std::unique_ptr<Solid>> owned;
    for (const OpenCsgProduct& product : products) {
        std::vector<OpenCSG::Primitive*> primitives;
        const std::size_t first = owned.size();
        for (int i : product.intersected)
            owned.push_back(std::make_unique<Solid>(solids[std::size_t(i)], OpenCSG::Intersection));
        for (int i : product.subtracted)
            owned.push_back(std::make_unique<Solid>(solids[std::size_t(i)], OpenCSG::Subtraction));
        for (std::size_t i = first; i < owned.size(); ++i)
            primitives.push_back(owned[i].get());
        glClearDepth(1.0);
        glClearStencil(0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        OpenCSG::render(primitives);
        const std::vector<float> productDepth = readDepth(width, height);
        // Measured with OpenCSG 1.5.0 on llvmpipe: a second render() in the same context
        // ignored its subtracted primitives (the product after the first came out
        // uncut) unless OpenCSG's offscreen buffers were released in between.
        OpenCSG::freeResources();
        for (std::size_t i = 0; i < depth.size(); ++i)
            depth[i] = std::min(depth[i], productDepth[i]);
    }
    return depth;
}

} // namespace trimlab::test
