#include "trim_renderer.h"

#include "gl/gl_error.h"
#include "gl/shader_library.h"
#include "gpu_scene.h"
#include "mfr/kplus_buffer.h"
#include "render_target.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <QElapsedTimer>
#include <QOpenGLContext>

#include <cmath>

namespace trimlab::render {

namespace {

// Spin iterations before a fragment gives up the lock (counted, never silent). Far above
// what llvmpipe needs (it serialises a pixel's fragments); bounds GPU livelock.
constexpr int kMaxSpin = 4096;

GlFunctions& checkedFunctions(const GlCapabilities& caps)
{
    if (const auto missing = missingRequirements(caps))
        throw GlUnavailableError(missing->toStdString());
    return currentGlFunctions();
}

// The clip plane in view space: planes transform with the inverse transpose.
glm::vec4 viewSpacePlane(const ClipPlane& plane, const glm::dmat4& view)
{
    return glm::vec4(glm::transpose(glm::inverse(view)) * plane.equation());
}

void setClipUniforms(GlFunctions& gl, GLuint program, const ClipPlane& clip, const glm::dmat4& view, double zNear)
{
    const glm::vec4 plane = viewSpacePlane(clip, view);
    gl.glUniform1i(gl.glGetUniformLocation(program, "u_clipEnabled"), clip.enabled ? 1 : 0);
    gl.glUniform4fv(gl.glGetUniformLocation(program, "u_clipPlaneView"), 1, glm::value_ptr(plane));
    gl.glUniform1f(gl.glGetUniformLocation(program, "u_zNear"), float(zNear));
}

} // namespace

TrimRenderer::TrimRenderer(QOpenGLContext& context)
    : m_capabilities(queryCapabilities(context)),
      m_gl(checkedFunctions(m_capabilities)),
      m_shaders(std::make_unique<ShaderLibrary>(m_gl)),
      m_scene(std::make_unique<GpuScene>(m_gl)),
      m_kplus(std::make_unique<KPlusBuffer>(m_gl, *m_shaders)),
      m_target(std::make_unique<RenderTarget>(m_gl)),
      m_counters(std::make_unique<FrameCounters>(m_gl)),
      m_emptyVao(m_gl),
      m_timer(m_gl)
{
    // Build the programs now so a broken shader is reported at start-up, not mid-frame.
    for (const char* name : {"kplus_clear", "kplus_store"})
        m_shaders->program(QString::fromLatin1(name));
    m_shaders->program(QStringLiteral("trim_resolve"), {QStringLiteral("K_MAX %1").arg(m_k)});
}

TrimRenderer::~TrimRenderer() = default;

void TrimRenderer::setScene(const Scene& scene)
{
    m_scene->upload(scene);
}

void TrimRenderer::setK(int k)
{
    if (k < 1 || k > KPlusBuffer::kMaxK)
        throw std::invalid_argument("k must be between 1 and " + std::to_string(KPlusBuffer::kMaxK) + ".");
    m_k = k;
}

void TrimRenderer::render(const Camera& camera, const TrimSettings& settings, int width, int height)
{
    QElapsedTimer wall;
    wall.start();
    m_target->resize(width, height);
    m_kplus->allocate(width, height, m_k);
    const glm::dmat4 projection = projectionMatrix(camera, double(width) / double(height));
    m_scene->setView(viewMatrix(camera));

    m_gl.glBeginQuery(GL_TIME_ELAPSED, m_timer.id());
    m_counters->reset();
    m_kplus->clear();
    storePass(camera, settings, projection);
    m_gl.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_ATOMIC_COUNTER_BARRIER_BIT);
    resolvePass(camera, settings, projection);
    m_gl.glEndQuery(GL_TIME_ELAPSED);

    GLuint64 elapsedNs = 0;
    m_gl.glGetQueryObjectui64v(m_timer.id(), GL_QUERY_RESULT, &elapsedNs);
    m_stats.counts = m_counters->read();
    m_stats.wallMilliseconds = double(wall.nsecsElapsed()) * 1e-6;
    // The GPU work happened inside the wall-clock interval, so a longer GPU time is a
    // driver error, not a measurement.
    const double gpuMs = double(elapsedNs) * 1e-6;
    m_stats.gpuMilliseconds = gpuMs <= m_stats.wallMilliseconds * 1.01 + 0.5 ? gpuMs : -1.0;
    m_stats.bufferMegabytes =
        double(m_kplus->memoryBytes() + m_target->memoryBytes() + m_scene->memoryBytes()) / (1024.0 * 1024.0);
    m_stats.width = width;
    m_stats.height = height;
    m_stats.k = m_k;
}

void TrimRenderer::storePass(const Camera& camera, const TrimSettings& settings, const glm::dmat4& projection)
{
    const GLuint program = m_shaders->program(QStringLiteral("kplus_store"));
    m_gl.glUseProgram(program);
    setClipUniforms(m_gl, program, settings.clip, viewMatrix(camera), camera.zNear);
    m_gl.glUniform1i(m_gl.glGetUniformLocation(program, "u_k"), m_k);
    m_gl.glUniform1i(m_gl.glGetUniformLocation(program, "u_maxSpin"), kMaxSpin);
    m_kplus->bindImages();
    m_counters->bind();

    m_target->bindForDrawing();
    // Every fragment counts, in any order: no depth test, no culling, no color writes
    // (the color mask also defuses llvmpipe's fully-covered-tile trap, PLATFORM.md).
    m_gl.glDisable(GL_DEPTH_TEST);
    m_gl.glDisable(GL_CULL_FACE);
    m_gl.glDisable(GL_BLEND);
    m_gl.glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    m_gl.glDepthMask(GL_FALSE);
    m_scene->draw(program, projection);
    m_gl.glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    m_gl.glDepthMask(GL_TRUE);
}

void TrimRenderer::resolvePass(const Camera& camera, const TrimSettings& settings, const glm::dmat4& projection)
{
    const GLuint program = m_shaders->program(QStringLiteral("trim_resolve"), {QStringLiteral("K_MAX %1").arg(m_k)});
    m_gl.glUseProgram(program);
    const double tanHalfY = std::tan(glm::radians(camera.fovyDegrees) * 0.5);
    const double aspect = double(m_target->width()) / double(m_target->height());
    const glm::mat4 projectionF(projection);
    m_gl.glUniform1i(m_gl.glGetUniformLocation(program, "u_trimEnabled"), settings.trimEnabled ? 1 : 0);
    m_gl.glUniform1i(m_gl.glGetUniformLocation(program, "u_rule"), static_cast<int>(settings.rule));
    m_gl.glUniform2f(m_gl.glGetUniformLocation(program, "u_viewportSize"), float(m_target->width()), float(m_target->height()));
    m_gl.glUniform2f(m_gl.glGetUniformLocation(program, "u_tanHalfFov"), float(tanHalfY * aspect), float(tanHalfY));
    m_gl.glUniformMatrix4fv(m_gl.glGetUniformLocation(program, "u_projection"), 1, GL_FALSE, glm::value_ptr(projectionF));
    m_kplus->bindImages();
    m_counters->bind();
    m_scene->bindStorage();

    m_target->bindForDrawing();
    m_gl.glEnable(GL_DEPTH_TEST);
    m_gl.glDepthFunc(GL_ALWAYS);
    m_gl.glBindVertexArray(m_emptyVao.id());
    m_gl.glDrawArrays(GL_TRIANGLES, 0, 3);
    m_gl.glBindVertexArray(0);
    m_gl.glDepthFunc(GL_LESS);
}

void TrimRenderer::blitTo(GLuint framebuffer)
{
    m_target->blitColorTo(framebuffer);
}

QImage TrimRenderer::readColor()
{
    return m_target->readColor();
}

KPlusOccupancy TrimRenderer::readOccupancy()
{
    return m_kplus->readOccupancy();
}

TrimImage TrimRenderer::readTrimImage()
{
    return m_target->readTrimImage();
}

} // namespace trimlab::render
