#include "render/trim_renderer.h"

#include "render/frame_limits.h"

#include "render/gl/gl_error.h"
#include "render/gl/shader_library.h"
#include "render/gl/wide_vector_state.h"
#include "render/frame/gpu_scene.h"
#include "render/mfr/method_factory.h"
#include "render/mfr/method_parameter_table.h"
#include "render/mfr/trim_frame.h"
#include "render/passes/object_windings.h"
#include "render/frame/render_target.h"

#include "core/trim/csg_expression.h"

#include <QElapsedTimer>
#include <QOpenGLContext>

#include <algorithm>
#include <optional>
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

std::string inspectionFeatures(const TrimSettings& settings)
{
    std::string features;
    auto add = [&](const char* feature) { features += (features.empty() ? "" : ", ") + std::string(feature); };
    if (settings.csg.enabled())
        add("CSG");
    if (settings.highlight.collisions)
        add("collision highlighting");
    if (settings.highlight.coplanar)
        add("coplanar highlighting");
    return features;
}

} // namespace

bool needsInspectionMethod(const TrimSettings& settings)
{
    return settings.perObjectWinding() || settings.highlight.coplanar || settings.xray();
}

std::optional<std::string> methodRefusal(const MethodInfo& info, bool dynamic, const TrimSettings& settings)
{
    const std::string name(info.displayName);
    if (dynamic && !info.dynamicRules)
        return name + " cannot run the dynamic rules: it never holds a pixel's reference and current fragments "
                      "together. Pick a buffer method (k+-buffer, S-buffer, AB_FP or AB_LL).";
    if (settings.xray() && !info.inspection)
        return name + " cannot render transparency (X-ray): it never holds all of a pixel's fragments in one pass. "
                      "Pick a buffer method (k+-buffer, S-buffer, K+B-SB, AB_FP or AB_LL).";
    if (needsInspectionMethod(settings) && !info.inspection)
        return name + " cannot render " + inspectionFeatures(settings) +
               ": it never holds all of a pixel's fragments in one pass. Pick a buffer method (k+-buffer, S-buffer, "
               "K+B-SB, AB_FP or AB_LL); clipping and capping work with every method.";
    return std::nullopt;
}

namespace {

// Throws std::invalid_argument when `settings` ask for something the mode or the scene
// cannot do (what the method cannot do is methodRefusal's), naming what to pick instead.
void checkInspection(const TrimMode& mode, const TrimSettings& settings, std::size_t objectCount)
{
    if (settings.xray() && mode.dynamic)
        throw std::invalid_argument("Transparency (X-ray) is not available with the dynamic rules; switch the "
                                    "classification to static to use it.");
    if (mode.dynamic && (needsInspectionMethod(settings) || settings.capping()))
        throw std::invalid_argument(
            "Capping, CSG and highlighting are not available with the dynamic rules; switch the "
            "classification to static to use them.");
    if (settings.csg.enabled() && settings.trimEnabled) {
        const int maxId = csgMaxObjectId(settings.csg.expression);
        if (maxId >= int(objectCount))
            throw std::invalid_argument("The CSG expression '" + formatCsgExpression(settings.csg.expression) +
                                        "' refers to object " + std::to_string(maxId) + ", but the scene has " +
                                        std::to_string(objectCount) + " object(s) (ids 0 to " +
                                        std::to_string(int(objectCount) - 1) + ").");
    }
    if (settings.perObjectWinding() && settings.highlight.collisions && objectCount > std::size_t(kMaxCsgOperands))
        throw std::invalid_argument("Collision highlighting tracks at most " + std::to_string(kMaxCsgOperands) +
                                    " objects; the scene has " + std::to_string(objectCount) + ".");
}

} // namespace

TrimRenderer::TrimRenderer(QOpenGLContext& context)
    : m_capabilities(queryCapabilities(context)),
      m_gl(checkedFunctions(m_capabilities)),
      m_resetWatch(context),
      m_shaders(std::make_unique<ShaderLibrary>(m_gl)),
      m_scene(std::make_unique<GpuScene>(m_gl)),
      m_target(std::make_unique<RenderTarget>(m_gl)),
      m_counters(std::make_unique<FrameCounters>(m_gl)),
      m_method(createFragmentMethod(FragmentMethodKind::KPlusArray, m_gl)),
      m_results(std::make_unique<FrameResultRing>(m_gl))
{
    m_clock.start();
    // Build the default method's programs now so a broken shader is reported at start-up.
    m_shaders->program(QStringLiteral("pixel_state_clear"));
    m_shaders->program(QStringLiteral("kplus_resolve"), {QStringLiteral("K_MAX %1").arg(m_parameters.k)});
}

TrimRenderer::~TrimRenderer() = default;

void TrimRenderer::setScene(const Scene& scene)
{
    const WideVectorStateScope wideVectorState; // the driver may leave it in use (wide_vector_state.h)
    m_scene->upload(scene);
}

void TrimRenderer::setMethod(FragmentMethodKind method)
{
    if (method != m_method->kind())
        m_method = createFragmentMethod(method, m_gl);
}

void TrimRenderer::setParameters(const MethodParameters& parameters)
{
    method_parameters::validateMethodParameters(parameters);
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
    const WideVectorStateScope wideVectorState; // the driver may leave it in use (wide_vector_state.h)
    if (const std::optional<std::string> refusal = methodRefusal(methodInfo(m_method->kind()), mode.dynamic, settings))
        throw std::invalid_argument(*refusal);
    checkInspection(mode, settings, scene.objectCount());
    checkFrameLimits(m_method->kind(), m_capabilities, m_parameters,
                     m_method->estimateBytes(width, height, m_parameters), width, height);
    const std::int64_t startNs = m_clock.nsecsElapsed();
    m_target->resize(width, height);
    const glm::dmat4 view = viewMatrix(camera);
    scene.setView(view);
    QStringList modeDefines;
    if (mode.dynamic)
        modeDefines << QStringLiteral("DYNAMIC_RULES");
    if (mode.dynamic && mode.characterize)
        modeDefines << QStringLiteral("DYNAMIC_CHARACTERIZE");
    ObjectWindingBuffer* objectWindings = prepareInspection(settings, scene.objectCount(), width, height, modeDefines);
    TrimFrame frame{m_gl,
                    *m_shaders,
                    m_capabilities,
                    scene,
                    *m_target,
                    *m_counters,
                    camera,
                    settings,
                    m_parameters,
                    view,
                    projectionMatrix(camera, double(width) / double(height)),
                    width,
                    height,
                    modeDefines,
                    mode.dynamicRule,
                    mode.referenceIsBase,
                    objectWindings};

    // Characterization passes of a pipelined frame are not timed: the frame's time is
    // its shown level's, and the ring keeps its slots for frames.
    const bool timed = !m_pipelined || !mode.characterize;
    std::vector<FrameResult> finished = m_results->poll();
    const std::uint64_t serial = ++m_serial;
    if (timed)
        m_results->begin(serial, finished);
    try {
        m_counters->reset();
        m_method->render(frame);
    } catch (...) {
        if (timed)
            m_results->end(*m_counters); // its result is dropped: no pending frame names it
        throw;
    }
    if (timed) {
        m_results->end(*m_counters);
        PendingFrame pending{FrameStats{}, startNs};
        FrameStats& stats = pending.stats;
        stats.serial = serial;
        stats.method = m_method->kind();
        stats.methodStats = m_method->stats();
        const std::size_t inspectionBytes = objectWindings ? objectWindings->memoryBytes() : 0;
        stats.bufferMegabytes =
            double(stats.methodStats.bytes + m_target->memoryBytes() + scene.memoryBytes() + inspectionBytes) /
            (1024.0 * 1024.0);
        stats.width = width;
        stats.height = height;
        stats.k = m_parameters.k;
        stats.issueMilliseconds = double(m_clock.nsecsElapsed() - startNs) * 1e-6;
        m_pending.push_back(pending);
    }
    (void)takeResults(finished);
    if (!m_pipelined)
        (void)takeResults(m_results->wait());
    m_resetWatch.throwIfReset(); // after a reset the counters and the image are garbage
}

void TrimRenderer::setPipelined(bool pipelined)
{
    if (!pipelined)
        finishFrames();
    m_pipelined = pipelined;
}

bool TrimRenderer::collectFrames()
{
    const WideVectorStateScope wideVectorState; // the driver may leave it in use (wide_vector_state.h)
    if (m_pending.empty())
        return false;
    const bool arrived = takeResults(m_results->poll());
    m_resetWatch.throwIfReset();
    return arrived;
}

void TrimRenderer::finishFrames()
{
    const WideVectorStateScope wideVectorState; // the driver may leave it in use (wide_vector_state.h)
    if (m_pending.empty())
        return;
    (void)takeResults(m_results->wait());
    m_resetWatch.throwIfReset();
}

// Results come in the order the frames were issued; the result of a frame whose render()
// threw names no pending frame and is dropped.
bool TrimRenderer::takeResults(const std::vector<FrameResult>& results)
{
    bool arrived = false;
    for (const FrameResult& result : results) {
        while (!m_pending.empty() && m_pending.front().stats.serial < result.serial)
            m_pending.pop_front();
        if (m_pending.empty() || m_pending.front().stats.serial != result.serial)
            continue;
        PendingFrame pending = m_pending.front();
        m_pending.pop_front();
        m_stats = pending.stats;
        m_stats.counts = result.counts;
        m_stats.wallMilliseconds = double(m_clock.nsecsElapsed() - pending.startNs) * 1e-6;
        m_stats.gpuMilliseconds = plausibleGpuMilliseconds(result.elapsedNs, m_stats.wallMilliseconds);
        arrived = true;
    }
    return arrived;
}

ObjectWindingBuffer* TrimRenderer::prepareInspection(const TrimSettings& settings, std::size_t objectCount, int width,
                                                     int height, QStringList& defines)
{
    if (settings.capping())
        defines << QStringLiteral("CAPPING");
    if (settings.highlight.coplanar)
        defines << QStringLiteral("COPLANAR_COUNT");
    if (settings.xray())
        defines << QStringLiteral("TRANSPARENCY");
    if (!settings.perObjectWinding())
        return nullptr;
    const int objects = int(std::clamp<std::size_t>(objectCount, 1, std::size_t(kMaxCsgOperands)));
    if (!m_objectWindings)
        m_objectWindings = std::make_unique<ObjectWindingBuffer>(m_gl);
    m_objectWindings->allocate(width, height, objects);
    defines << QStringLiteral("OBJECT_WINDINGS %1").arg(objects);
    return m_objectWindings.get();
}

void TrimRenderer::blitTo(GLuint framebuffer)
{
    const WideVectorStateScope wideVectorState; // the driver may leave it in use (wide_vector_state.h)
    m_target->blitColorTo(framebuffer);
}

QImage TrimRenderer::readColor()
{
    const WideVectorStateScope wideVectorState; // the driver may leave it in use (wide_vector_state.h)
    return m_target->readColor();
}

TrimImage TrimRenderer::readTrimImage()
{
    const WideVectorStateScope wideVectorState; // the driver may leave it in use (wide_vector_state.h)
    return m_target->readTrimImage();
}

std::optional<PixelOccupancy> TrimRenderer::readOccupancy()
{
    const WideVectorStateScope wideVectorState; // the driver may leave it in use (wide_vector_state.h)
    return m_method->readOccupancy();
}

} // namespace trimlab::render
