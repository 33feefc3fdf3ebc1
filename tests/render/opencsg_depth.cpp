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

/// A solid drawn from a vertex buffer of its corners (positions only), as OpenCSG calls it
/// once per pass.
class Solid final : public OpenCSG::Primitive {
public:
    Solid(GLuint buffer, GLsizei vertices, unsigned convexity, OpenCSG::Operation operation)
        : OpenCSG::Primitive(operation, convexity), m_buffer(buffer), m_vertices(vertices)
    {
    }
    void render() override
    {
        glBindBuffer(GL_ARRAY_BUFFER, m_buffer);
        glEnableClientState(GL_VERTEX_ARRAY);
        glVertexPointer(3, GL_FLOAT, 0, nullptr);
        glDrawArrays(GL_TRIANGLES, 0, m_vertices);
        glDisableClientState(GL_VERTEX_ARRAY);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
    }

private:
    GLuint m_buffer;
    GLsizei m_vertices;
};

/// An RGBA8 + depth24/stencil8 framebuffer object.
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
    void bind() const { glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer); }

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

OpenCSG::Algorithm openCsgAlgorithm(OpenCsgAlgorithm algorithm)
{
    switch (algorithm) {
    case OpenCsgAlgorithm::Goldfeather:
        return OpenCSG::Goldfeather;
    case OpenCsgAlgorithm::Scs:
        return OpenCSG::SCS;
    case OpenCsgAlgorithm::Automatic:
        break;
    }
    return OpenCSG::Automatic;
}

} // namespace

struct OpenCsgRenderer::Gl {
    std::unique_ptr<Framebuffer> framebuffer;
    std::vector<GLuint> buffers; ///< one per solid
    /// Per product its primitives; they live as long as the renderer: OpenCSG keys internal
    /// state by primitive address.
    std::vector<std::vector<std::unique_ptr<Solid>>> products;
    GLuint query = 0;
};

OpenCsgRenderer::OpenCsgRenderer(const std::vector<OpenCsgSolid>& solids, std::vector<OpenCsgProduct> products,
                                 int width, int height, OpenCsgAlgorithm algorithm)
    : m_products(std::move(products)), m_width(width), m_height(height), m_algorithm(algorithm)
{
    glewExperimental = GL_TRUE;
    if (const GLenum status = glewInit(); status != GLEW_OK) {
        m_error = std::string("glewInit failed: ") + reinterpret_cast<const char*>(glewGetErrorString(status));
        return;
    }
    m_gl = std::make_unique<Gl>();
    m_gl->framebuffer = std::make_unique<Framebuffer>(width, height);
    if (!m_gl->framebuffer->complete()) {
        m_error = "the OpenCSG framebuffer is incomplete";
        return;
    }
    m_gl->buffers.resize(solids.size());
    glGenBuffers(GLsizei(solids.size()), m_gl->buffers.data());
    for (std::size_t i = 0; i < solids.size(); ++i) {
        const std::vector<glm::vec3> corners(solids[i].corners.begin(), solids[i].corners.end());
        glBindBuffer(GL_ARRAY_BUFFER, m_gl->buffers[i]);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(corners.size() * sizeof(glm::vec3)), corners.data(), GL_STATIC_DRAW);
    }
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    const auto solid = [&](int i, OpenCSG::Operation operation) {
        const std::size_t index = std::size_t(i);
        return std::make_unique<Solid>(m_gl->buffers[index], GLsizei(solids[index].corners.size()),
                                       solids[index].convexity, operation);
    };
    for (const OpenCsgProduct& product : m_products) {
        std::vector<std::unique_ptr<Solid>>& primitives = m_gl->products.emplace_back();
        for (int i : product.intersected)
            primitives.push_back(solid(i, OpenCSG::Intersection));
        for (int i : product.subtracted)
            primitives.push_back(solid(i, OpenCSG::Subtraction));
    }
    if (GLEW_ARB_timer_query || GLEW_VERSION_3_3)
        glGenQueries(1, &m_gl->query);
}

OpenCsgRenderer::~OpenCsgRenderer()
{
    if (!m_gl)
        return;
    OpenCSG::freeResources();
    if (m_gl->query != 0)
        glDeleteQueries(1, &m_gl->query);
    if (!m_gl->buffers.empty())
        glDeleteBuffers(GLsizei(m_gl->buffers.size()), m_gl->buffers.data());
}

double OpenCsgRenderer::render(const glm::dmat4& view, const glm::dmat4& projection)
{
    if (!m_error.empty())
        return -1.0;
    m_gl->framebuffer->bind();
    glViewport(0, 0, m_width, m_height);
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixd(glm::value_ptr(projection));
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixd(glm::value_ptr(view));
    OpenCSG::setOption(OpenCSG::AlgorithmSetting, openCsgAlgorithm(m_algorithm));
    OpenCSG::setOption(OpenCSG::OffscreenSetting, OpenCSG::FrameBufferObject);
    m_depth.assign(std::size_t(m_width) * std::size_t(m_height), 1.0f);
    double gpuMs = m_gl->query != 0 ? 0.0 : -1.0;
    for (const std::vector<std::unique_ptr<Solid>>& product : m_gl->products) {
        std::vector<OpenCSG::Primitive*> primitives;
        for (const std::unique_ptr<Solid>& primitive : product)
            primitives.push_back(primitive.get());
        if (m_gl->query != 0)
            glBeginQuery(GL_TIME_ELAPSED, m_gl->query);
        glClearDepth(1.0);
        glClearStencil(0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        OpenCSG::render(primitives);
        if (m_gl->query != 0) {
            glEndQuery(GL_TIME_ELAPSED);
            GLuint64 elapsedNs = 0;
            glGetQueryObjectui64v(m_gl->query, GL_QUERY_RESULT, &elapsedNs);
            gpuMs += double(elapsedNs) * 1e-6;
        }
        const std::vector<float> productDepth = readDepth(m_width, m_height);
        for (std::size_t i = 0; i < m_depth.size(); ++i)
            m_depth[i] = std::min(m_depth[i], productDepth[i]);
        // Measured with OpenCSG 1.5.0 on llvmpipe: a second render() in the same context —
        // the next product, or the same one in the next frame — ignored its subtracted
        // primitives (or, for an intersection, most of the other operand) unless
        // OpenCSG's offscreen buffers were released in between. OpenCSG allocates them
        // again in the next render(), inside the timed query.
        OpenCSG::freeResources();
    }
    return gpuMs;
}

std::vector<float> renderOpenCsgDepth(const std::vector<OpenCsgSolid>& solids,
                                      const std::vector<OpenCsgProduct>& products, const glm::dmat4& view,
                                      const glm::dmat4& projection, int width, int height, std::string* error)
{
    OpenCsgRenderer renderer(solids, products, width, height, OpenCsgAlgorithm::Goldfeather);
    if (!renderer.error().empty()) {
        if (error)
            *error = renderer.error();
        return {};
    }
    (void)renderer.render(view, projection);
    return renderer.depth();
}

} // namespace trimlab::test
