#include "trim_renderer.h"

#include "frame_limits.h"

#include "gl/gl_error.h"
#include "gl/shader_library.h"
#include "gpu_scene.h"
#include "mfr/method_factory.h"
#include "mfr/trim_frame.h"
#include "render_target.h"

#include <QElapsedTimer>
#include <QOpenGLContext>

#include <stdexcept>
#include <string>

namespace trimlab::render {

namespace {

GlFunctions& checkedFunctions(const GlCapabilities& caps)
{
    if (const auto missing = missingRequirements(caps))
        throw GlUnavailableError(missing->toStdString());
    return currentGlFunctions();
}

// The GPU work happened inside the wall-clock interval, so a longer GPU time is a driver
// error, not a measurement.
double plausibleGpuMilliseconds(GLuint64 elapsedNs, double wallMs)
{
    const double gpuMs = double(elapsedNs) * 1e-6;
    return gpuMs <= wallMs * 1.01 + 0.5 ? gpuMs : -1.0;
}

} // namespace

TrimRenderer::TrimRenderer(QOpenGLContext& context)
    : m_capabilities(queryCapabilities(context)),
      m_gl(checkedFunctions(m_capabilities)),
      m_shaders(std::make_unique<ShaderLibrary>(m_gl)),
      m_scene(std::make_unique<GpuScene>(m_gl)),
      m_target(std::make_unique<RenderTarget>(m_gl)),
      m_counters(std::make_unique<FrameCounters>(m_gl)),
      m_method(createFragmentMethod(FragmentMethodKind::KPlusArray, m_gl)),
      m_timer(m_gl)
{
    // Build the default method's programs now so a broken shader is reported at start-up.
    m_shaders->program(QStringLiteral("pixel_state_clear"));
    m_shaders->program(QStringLiteral("kplus_resolve"), {QStringLiteral("K_MAX %1").arg(m_parameters.k)});
}

TrimRenderer::~TrimRenderer() = default;

void TrimRenderer::setScene(const Scene& scene)
{
    m_scene->upload(scene);
}

void TrimRenderer::setMethod(FragmentMethodKind method)
{
    if (method != m_method->kind())
        m_method = createFragmentMethod(method, m_gl);
}

void TrimRenderer::setParameters(const MethodParameters& parameters)
{
    if (parameters.k < 1 || parameters.k > MethodParameters::kMaxK)
        throw std::invalid_argument("k must be between 1 and " + std::to_string(MethodParameters::kMaxK) + ".");
    if (parameters.sharedCounters < 1)
        throw std::invalid_argument("the number of shared counters must be at least 1.");
    m_parameters = parameters;
}

void TrimRenderer::setK(int k)
{
    MethodParameters parameters = m_parameters;
    parameters.k = k;
    setParameters(parameters);
}

std::optional<std::size_t> TrimRenderer::estimateMethodBytes(int width, int height) const
{
    return m_method->estimateBytes(width, height, m_parameters);
}

void TrimRenderer::render(const Camera& camera, const TrimSettings& settings, int width, int height)
{
    render(*m_scene, TrimMode{}, camera, settings, width, height);
}

void TrimRenderer::render(GpuScene& scene, const TrimMode& mode, const Camera& camera, const TrimSettings& settings,
                          int width, int height)
{
    const MethodInfo& info = methodInfo(m_method->kind());
    if (mode.dynamic && !info.dynamicRules)
        throw std::invalid_argument(std::string(info.displayName) +
                                    " cannot run the dynamic rules: it never holds a pixel's reference and current "
                                    "fragments together. Pick a buffer method (k+-buffer, S-buffer, AB_FP or AB_LL).");
    checkFrameLimits(m_method->kind(), m_capabilities, m_parameters,
                     m_method->estimateBytes(width, height, m_parameters), width, height);
    QElapsedTimer wall;
    wall.start();
    m_target->resize(width, height);
    const glm::dmat4 view = viewMatrix(camera);
    scene.setView(view);
    QStringList modeDefines;
    if (mode.dynamic)
        modeDefines << QStringLiteral("DYNAMIC_RULES");
    if (mode.dynamic && mode.characterize)
        modeDefines << QStringLiteral("DYNAMIC_CHARACTERIZE");
    TrimFrame frame{m_gl,        *m_shaders, m_capabilities, scene,          *m_target,
                    *m_counters, camera,     settings,       m_parameters,   view,
                    projectionMatrix(camera, double(width) / double(height)), width, height, modeDefines,
                    mode.dynamicRule, mode.referenceIsBase};

    m_gl.glBeginQuery(GL_TIME_ELAPSED, m_timer.id());
    m_counters->reset();
    m_method->render(frame);
    m_gl.glEndQuery(GL_TIME_ELAPSED);

    GLuint64 elapsedNs = 0;
    m_gl.glGetQueryObjectui64v(m_timer.id(), GL_QUERY_RESULT, &elapsedNs);
    m_stats.method = m_method->kind();
    m_stats.counts = m_counters->read();
    m_stats.methodStats = m_method->stats();
    m_stats.wallMilliseconds = double(wall.nsecsElapsed()) * 1e-6;
    m_stats.gpuMilliseconds = plausibleGpuMilliseconds(elapsedNs, m_stats.wallMilliseconds);
    m_stats.bufferMegabytes =
        double(m_stats.methodStats.bytes + m_target->memoryBytes() + scene.memoryBytes()) / (1024.0 * 1024.0);
    m_stats.width = width;
    m_stats.height = height;
    m_stats.k = m_parameters.k;
}

void TrimRenderer::blitTo(GLuint framebuffer)
{
    m_target->blitColorTo(framebuffer);
}

QImage TrimRenderer::readColor()
{
    return m_target->readColor();
}

TrimImage TrimRenderer::readTrimImage()
{
    return m_target->readTrimImage();
}

std::optional<PixelOccupancy> TrimRenderer::readOccupancy()
{
    return m_method->readOccupancy();
}

} // namespace trimlab::render
