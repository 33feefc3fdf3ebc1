#include "ui/viewport/viewport_widget.h"

#include "render/gl/context_reset.h"
#include "render/gl/gl_error.h"
#include "render/gl/offscreen_gl_context.h"
#include "render/frame/gpu_scene.h"
#include "render/mfr/fragment_method.h"
#include "core/trim/trim_shading.h"

#include <QCoreApplication>
#include <QEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace trimlab::ui {

namespace {

/// Pixels of margin around the message painted into the view.
constexpr int kMessageMargin = 24;
/// QWheelEvent::angleDelta of one wheel notch (15° in eighths of a degree).
constexpr double kAngleDeltaPerNotch = 120.0;

} // namespace

ViewportWidget::ViewportWidget(QWidget* parent) : QOpenGLWidget(parent), m_cpuStill(new CpuStillRender(this))
{
    connect(m_cpuStill, &CpuStillRender::ready, this, qOverload<>(&ViewportWidget::update));
    connect(m_cpuStill, &CpuStillRender::failed, this, [this](const QString& message) {
        setError(tr("Neither the GPU nor the CPU reference could render this view: %1").arg(message));
        update();
    });
    setFormat(render::OffscreenGlContext::requestedFormat());
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(160, 120);
    setToolTip(tr("Left drag: orbit · Right/middle or Shift+left drag: pan · Wheel: zoom (Ctrl: toward the "
                  "cursor) · Double click or F: fit · Ctrl+left drag on an object: move it (when the Scene panel "
                  "allows)"));
}

ViewportWidget::~ViewportWidget()
{
    releaseGl();
}

void ViewportWidget::setScene(std::shared_ptr<const Scene> scene)
{
    m_scene = std::move(scene);
    m_cpuScene.reset();
    m_orbit.setSceneBounds(m_scene ? m_scene->worldBounds() : Bounds{});
    m_sceneUploaded = false;
    m_resetPending = true;
    m_lastFrame.reset();
    m_pose.clear();
    m_vertexColors.clear();
    m_chain.reset(); // a chain belongs to the previous scene's mesh
    m_level.reset();
    m_policy.reset();
    update();
}

void ViewportWidget::replaceScene(std::shared_ptr<const Scene> scene)
{
    const bool keepView = !m_resetPending;
    setScene(std::move(scene));
    m_resetPending = !keepView; // a view never shown yet is still fitted on the first frame
}

void ViewportWidget::setSceneTransforms(std::shared_ptr<const Scene> scene)
{
    if (!m_scene || !scene || scene->objects.size() != m_scene->objects.size())
        throw std::invalid_argument("setSceneTransforms: the new scene does not have the shown scene's objects.");
    for (std::size_t i = 0; i < scene->objects.size(); ++i) {
        if (scene->objects[i].mesh.vertexCount() != m_scene->objects[i].mesh.vertexCount() ||
            scene->objects[i].mesh.triangleCount() != m_scene->objects[i].mesh.triangleCount())
            throw std::invalid_argument("setSceneTransforms: object " + std::to_string(i) +
                                        " has another mesh than the one shown.");
    }
    m_scene = std::move(scene);
    m_orbit.setSceneBounds(m_scene->worldBounds()); // the depth range must enclose the moved object
    m_transformsDirty = true;
    update();
}

void ViewportWidget::setTool(ViewportTool* tool)
{
    m_tool = tool;
    setMouseTracking(tool != nullptr); // hover feedback (the brush's region) needs moves without buttons
    if (m_drag == Drag::Tool)
        m_drag = Drag::None;
}

void ViewportWidget::setDynamicChain(std::shared_ptr<const DynamicChain> chain)
{
    m_chain = std::move(chain);
    m_policy.clearStop();
    m_level.reset();
    m_chainDirty = m_chain != nullptr;
    m_levelDirty = false;
    update();
}

void ViewportWidget::setDynamicShownLevel(std::shared_ptr<const DynamicChainLevel> level)
{
    if (!m_chain)
        return;
    m_level = std::move(level);
    m_levelDirty = m_level != nullptr;
    update();
}

const DynamicChainLevel* ViewportWidget::dynamicShownLevel() const
{
    if (m_level)
        return m_level.get();
    return m_chain && !m_chain->levels.empty() ? &m_chain->levels.back() : nullptr;
}

std::optional<TrimPixel> ViewportWidget::trimPixelAt(QPointF position)
{
    if (!m_lastFrame)
        return std::nullopt;
    if (m_trimCache.pixels.empty())
        m_trimCache = readTrimImage();
    const QPointF device = devicePosition(position);
    const int x = int(std::floor(device.x()));
    const int y = int(std::floor(device.y()));
    if (x < 0 || y < 0 || x >= m_trimCache.width || y >= m_trimCache.height)
        return std::nullopt;
    return m_trimCache.at(x, y);
}

void ViewportWidget::setViewBounds(const Bounds& bounds)
{
    m_orbit.setSceneBounds(bounds);
    update();
}

void ViewportWidget::showPose(const std::vector<glm::vec3>& positions)
{
    const std::size_t expected = m_scene && !m_scene->objects.empty() ? m_scene->objects.front().mesh.vertexCount() : 0;
    if (positions.size() != expected || expected == 0)
        throw std::invalid_argument("showPose: the scene's first object has " + std::to_string(expected) +
                                    " vertices, the pose " + std::to_string(positions.size()) + ".");
    m_pose = positions;
    m_poseDirty = true;
    m_cpuScene.reset();
    update();
}

void ViewportWidget::setVertexColors(std::vector<std::uint32_t> rgba8)
{
    std::size_t vertices = 0;
    if (m_scene)
        for (const SceneObject& object : m_scene->objects)
            vertices += object.mesh.vertexCount();
    if (!rgba8.empty() && rgba8.size() != vertices)
        throw std::invalid_argument("setVertexColors: the scene has " + std::to_string(vertices) + " vertices, got " +
                                    std::to_string(rgba8.size()) + " colors.");
    m_vertexColors = std::move(rgba8);
    m_colorsDirty = true;
    m_dynamicColorsDirty = true;
    update();
}

// Brings the renderer's scene buffers up to date: the scene itself after setScene() or a
// new context, then the pose and colors when they changed or the scene was re-uploaded.
// The context must be current.
void ViewportWidget::syncGpuScene()
{
    if (!m_sceneUploaded) {
        m_renderer->setScene(*m_scene);
        m_sceneUploaded = true;
        m_transformsDirty = false; // the upload carried the current matrices
        m_poseDirty = !m_pose.empty();
        m_colorsDirty = !m_vertexColors.empty();
    }
    if (m_transformsDirty) {
        for (std::size_t i = 0; i < m_scene->objects.size(); ++i)
            m_renderer->gpuScene().setModelMatrix(i, m_scene->objects[i].modelMatrix);
        m_transformsDirty = false;
    }
    if (m_poseDirty) {
        m_renderer->gpuScene().updatePositions(0, m_pose);
        m_poseDirty = false;
    }
    if (m_colorsDirty) {
        m_renderer->gpuScene().setVertexColors(m_vertexColors);
        m_colorsDirty = false;
    }
}

void ViewportWidget::setTrimSettings(const TrimSettings& settings)
{
    m_settings = settings;
    update();
}

void ViewportWidget::setMethod(render::FragmentMethodKind method)
{
    m_policy.choose(method);
    applyMethod();
    update();
}

void ViewportWidget::setMethodParameters(const render::MethodParameters& parameters)
{
    m_parameters = parameters;
    m_parameters.k = std::clamp(parameters.k, 1, render::MethodParameters::kMaxK);
    m_parameters.sharedCounters = std::max(parameters.sharedCounters, 1);
    m_policy.reset();
    applyMethod();
    update();
}

void ViewportWidget::setK(int k)
{
    render::MethodParameters parameters = m_parameters;
    parameters.k = k;
    setMethodParameters(parameters);
}

// Hands the choice to the renderer at once (its storage follows on the next frame), so
// memoryEstimate() answers for it before anything is allocated.
void ViewportWidget::applyMethod()
{
    if (!m_renderer)
        return;
    makeCurrent(); // replacing the method object releases its GL storage
    try {
        m_renderer->setMethod(effectiveMethod());
        m_renderer->setParameters(m_parameters);
    } catch (const std::exception& e) {
        setError(tr("The method could not be set up: %1").arg(QString::fromStdString(e.what())));
    }
    doneCurrent();
}

MemoryEstimate ViewportWidget::memoryEstimate() const
{
    if (!m_renderer)
        return {};
    const QSize size = framePixelSize();
    return {true, m_renderer->estimateMethodBytes(size.width(), size.height()), size};
}

MethodMeasurement ViewportWidget::measureMethod(render::FragmentMethodKind method, int frames)
{
    if (!m_renderer)
        throw std::runtime_error(m_error.isEmpty() ? "OpenGL is not available." : m_error.toStdString());
    if (!m_scene || m_scene->empty())
        throw std::runtime_error("There is no scene to render.");
    MethodMeasurement result;
    makeCurrent();
    try {
        runMeasurement(method, frames, result);
    } catch (...) {
        m_renderer->setMethod(effectiveMethod());
        doneCurrent();
        update();
        throw;
    }
    m_renderer->setMethod(effectiveMethod());
    doneCurrent();
    update();
    return result;
}

void ViewportWidget::runMeasurement(render::FragmentMethodKind method, int frames, MethodMeasurement& result)
{
    syncGpuScene();
    applyPendingReset();
    const QSize size = framePixelSize();
    const Camera camera = m_orbit.camera();
    m_renderer->setMethod(method);
    m_renderer->setParameters(m_parameters);
    m_renderer->render(camera, m_settings, size.width(), size.height()); // warm-up: shaders, storage
    for (int i = 0; i < frames; ++i) {
        m_renderer->render(camera, m_settings, size.width(), size.height());
        result.times.add(m_renderer->lastStats());
    }
    result.lastStats = m_renderer->lastStats();
}

Camera ViewportWidget::camera() const
{
    if (!m_resetPending)
        return m_orbit.camera();
    OrbitController reset = m_orbit;
    reset.fit(aspect());
    return reset.camera();
}

void ViewportWidget::applyPendingReset()
{
    if (!m_resetPending)
        return;
    m_orbit.fit(aspect());
    m_resetPending = false;
}

void ViewportWidget::setCamera(const Camera& camera)
{
    m_orbit.setCamera(camera);
    m_resetPending = false;
    update();
}

void ViewportWidget::fitToView()
{
    applyPendingReset();
    m_orbit.fitKeepingDirection(aspect());
    update();
}

void ViewportWidget::resetView()
{
    m_orbit.fit(aspect());
    m_resetPending = false;
    update();
}

QSize ViewportWidget::framePixelSize() const
{
    // QOpenGLWidget sizes its framebuffer as size() × devicePixelRatio(), rounded.
    const QSize size = this->size() * devicePixelRatio();
    return size.expandedTo(QSize(1, 1));
}

double ViewportWidget::aspect() const
{
    const QSize size = framePixelSize();
    return double(size.width()) / double(size.height());
}

QString ViewportWidget::openGlProblem()
{
    try {
        const render::OffscreenGlContext probe;
        return {};
    } catch (const render::GlError& e) {
        return QString::fromStdString(e.what());
    }
}

void ViewportWidget::setUnavailable(const QString& reason)
{
    m_error = reason;
    m_reportedError = reason;
}

std::optional<render::GlCapabilities> ViewportWidget::capabilities() const
{
    if (!m_renderer)
        return std::nullopt;
    return m_renderer->capabilities();
}

QImage ViewportWidget::readColorImage()
{
    if (!m_renderer || !m_lastFrame)
        return {};
    makeCurrent();
    QImage image = m_renderer->readColor();
    doneCurrent();
    return image;
}

TrimImage ViewportWidget::readTrimImage()
{
    if (!m_renderer || !m_lastFrame)
        return {};
    makeCurrent();
    TrimImage image = m_renderer->readTrimImage();
    doneCurrent();
    return image;
}

void ViewportWidget::initializeGL()
{
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &ViewportWidget::releaseGl, Qt::UniqueConnection);
    ++m_contextsInitialized;
    m_sceneUploaded = false;
    try {
        m_renderer = std::make_unique<render::TrimRenderer>(*context());
        m_renderer->setMethod(effectiveMethod());
        m_renderer->setParameters(m_parameters);
        setError({});
    } catch (const render::GlError& e) {
        setError(QString::fromStdString(e.what()));
    } catch (const std::exception& e) {
        setError(tr("The renderer could not start: %1").arg(QString::fromStdString(e.what())));
    }
}

void ViewportWidget::releaseGl()
{
    if (!m_renderer)
        return;
    makeCurrent();
    m_dynamic.reset(); // its GL objects go first: it holds a reference to the renderer
    m_renderer.reset();
    doneCurrent();
    m_sceneUploaded = false;
    m_chainDirty = m_chain != nullptr;
    m_levelDirty = m_level != nullptr;
}

void ViewportWidget::recoverFromContextLoss(const QString& reason)
{
    m_lastFrame.reset();
    m_trimCache = {};
    (void)applyRecovery(m_policy.contextLost(reason.toStdString(), frameDemands()));
    QMetaObject::invokeMethod(this, &ViewportWidget::recreateContext, Qt::QueuedConnection);
}

// What Qt itself does when a window's graphics device is lost: QOpenGLWidget drops its
// context and framebuffer (aboutToBeDestroyed → releaseGl) and, shown, creates new ones
// at once (initializeGL). Never from inside paintGL, hence queued.
void ViewportWidget::recreateContext()
{
    QEvent aboutToChange(QEvent::WindowAboutToChangeInternal);
    QCoreApplication::sendEvent(this, &aboutToChange);
    QEvent changed(QEvent::WindowChangeInternal);
    QCoreApplication::sendEvent(this, &changed);
    update();
}

void ViewportWidget::resizeGL(int, int)
{
    m_policy.reset(); // the chosen method may fit the new size
    emit framePixelSizeChanged(framePixelSize());
}

void ViewportWidget::paintGL()
{
    if (m_renderer && !context()->isValid()) { // Qt saw the reset first (platforms with reset notification)
        clearToBackground();
        recoverFromContextLoss(QString::fromStdString(render::contextResetMessage(render::ContextReset::Unknown)));
        return;
    }
    if (!m_renderer || m_policy.stopped()) {
        clearToBackground();
        paintMessage(m_error.isEmpty() ? tr("OpenGL is not available.") : m_error);
        return;
    }
    if (!m_scene || m_scene->empty()) {
        clearToBackground();
        paintMessage(tr("No scene. Open a mesh with File ▸ Open… or drop a mesh file here."));
        return;
    }
    if (m_policy.showsCpuStill()) {
        paintCpuStill();
        return;
    }
    try {
        renderWithFallbacks();
        if (m_policy.showsCpuStill()) {
            paintCpuStill();
            return;
        }
    } catch (const render::GlContextLostError& e) {
        clearToBackground();
        recoverFromContextLoss(QString::fromStdString(e.what()));
        return;
    } catch (const render::GlError& e) {
        setError(QString::fromStdString(e.what()));
    } catch (const std::invalid_argument& e) {
        // E.g. a peeling method asked for the dynamic rules: the message says what to pick.
        setError(QString::fromStdString(e.what()));
    } catch (const std::exception& e) {
        setError(tr("Rendering failed: %1").arg(QString::fromStdString(e.what())));
    }
    if (!m_error.isEmpty()) {
        m_lastFrame.reset();
        clearToBackground();
        paintMessage(m_error);
        return;
    }
    m_policy.frameRendered();
    emit frameRendered(m_lastFrame->stats);
}

void ViewportWidget::renderFrame()
{
    const QSize size = framePixelSize();
    syncGpuScene();
    applyPendingReset();
    m_renderer->setMethod(effectiveMethod());
    m_renderer->setParameters(m_parameters);
    const Camera camera = m_orbit.camera();
    if (m_chain && m_settings.trimEnabled) {
        renderDynamicFrame(camera, size);
    } else {
        m_renderer->render(camera, m_settings, size.width(), size.height());
        m_dynamicStats.reset();
    }
    m_renderer->blitTo(defaultFramebufferObject());
    recordFrame(camera, size);
    setError({});
}

// Out of GPU memory (checked before allocating, or a failed allocation): the next method
// of the fallback chain renders the frame; none left → the CPU still (render/frame_policy.h).
void ViewportWidget::renderWithFallbacks()
{
    for (;;) {
        try {
            renderFrame();
            return;
        } catch (const render::GpuMemoryError& e) {
            if (!applyRecovery(m_policy.outOfMemory(e.what(), frameDemands())))
                return;
        }
    }
}

render::FrameDemands ViewportWidget::frameDemands() const
{
    return {m_chain && m_settings.trimEnabled, render::needsInspectionMethod(m_settings)};
}

// Carries out what the policy decided after a failed frame; true when the frame should
// be rendered again with the policy's method.
bool ViewportWidget::applyRecovery(const render::FrameRecovery& recovery)
{
    const QString message = QString::fromStdString(recovery.message);
    switch (recovery.action) {
    case render::FrameRecovery::Action::OtherMethod:
        m_lastFrame.reset();
        emit memoryFallback(message);
        return true;
    case render::FrameRecovery::Action::CpuStill:
        m_lastFrame.reset();
        emit memoryFallback(message);
        return false;
    case render::FrameRecovery::Action::Refuse:
        m_lastFrame.reset();
        throw render::GpuMemoryError(recovery.message);
    case render::FrameRecovery::Action::Recreate:
        emit contextLost(message);
        return false;
    case render::FrameRecovery::Action::Stop:
        setError(message);
        return false;
    }
    return false;
}

QImage ViewportWidget::cpuStillImage() const
{
    return m_policy.showsCpuStill() && m_cpuStill->shown() ? m_cpuStill->image() : QImage();
}

// The CPU reference of the current view, drawn when ready; the previous still (or a note)
// meanwhile.
void ViewportWidget::paintCpuStill()
{
    applyPendingReset();
    if (!m_cpuScene && m_scene) {
        if (m_pose.empty()) {
            m_cpuScene = m_scene;
        } else {
            auto posed = std::make_shared<Scene>(*m_scene);
            posed->objects.front().mesh.positions = m_pose;
            m_cpuScene = std::move(posed);
        }
    }
    const CpuStillRender::Request request{m_cpuScene, m_orbit.camera(), m_settings, framePixelSize()};
    m_cpuStill->request(request);
    clearToBackground();
    QPainter painter(this);
    if (m_cpuStill->shown() && m_cpuStill->shown()->scene == m_cpuScene)
        painter.drawImage(rect(), m_cpuStill->image());
    painter.setPen(QColor(235, 235, 235));
    const bool current = m_cpuStill->shown() && m_cpuStill->shown()->sameView(request);
    painter.drawText(rect().adjusted(kMessageMargin, kMessageMargin, -kMessageMargin, -kMessageMargin),
                     Qt::AlignTop | Qt::AlignLeft,
                     current ? tr("CPU reference (no GPU method fits this view)") : tr("Rendering on the CPU…"));
}

// The chain's levels are uploaded only when the chain changed; a drag replaces only the
// shown level, so the earlier sets' characterizations stay cached.
void ViewportWidget::renderDynamicFrame(const Camera& camera, QSize size)
{
    if (!m_dynamic) {
        m_dynamic = std::make_unique<render::DynamicTrimRenderer>(*m_renderer);
        m_dynamicColorsDirty = true;
    }
    if (m_chainDirty) {
        m_dynamic->setChain(*m_chain);
        m_chainDirty = false;
        m_levelDirty = m_level != nullptr;
    }
    if (m_levelDirty) {
        m_dynamic->setShownLevel(*m_level);
        m_levelDirty = false;
    }
    if (m_dynamicColorsDirty) {
        // The designed mesh is the scene's only object, so the scene's colors are per mesh vertex.
        m_dynamic->setShownVertexColors(m_vertexColors);
        m_dynamicColorsDirty = false;
    }
    m_dynamic->render(camera, m_settings, size.width(), size.height());
    m_dynamicStats = m_dynamic->lastStats();
}

void ViewportWidget::recordFrame(const Camera& camera, QSize size)
{
    const render::FrameStats& stats = m_renderer->lastStats();
    m_trimCache = TrimImage(); // read again on demand: the frame changed
    ViewportFrame frame{camera, m_settings, m_parameters.k, m_parameters, size, stats, std::nullopt, m_scene};
    const render::FrameCounts& counts = stats.counts;
    if (counts.overflowPixels > 0 || counts.unresolvedPixels > 0 || counts.fragmentsLost > 0) {
        const std::optional<render::PixelOccupancy> occupancy = m_renderer->readOccupancy();
        if (occupancy && !occupancy->held.empty())
            frame.largestPixelCount = *std::max_element(occupancy->held.begin(), occupancy->held.end());
    }
    m_lastFrame = std::move(frame);
}

void ViewportWidget::clearToBackground()
{
    QOpenGLFunctions* gl = context()->functions();
    gl->glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
    gl->glClearColor(kBackgroundColor.r, kBackgroundColor.g, kBackgroundColor.b, 1.0f);
    gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void ViewportWidget::paintMessage(const QString& text)
{
    QPainter painter(this);
    painter.setPen(QColor(235, 235, 235));
    const QRect area = rect().adjusted(kMessageMargin, kMessageMargin, -kMessageMargin, -kMessageMargin);
    painter.drawText(area, Qt::AlignCenter | Qt::TextWordWrap, text);
}

void ViewportWidget::setError(const QString& message)
{
    m_error = message;
    if (message.isEmpty()) {
        m_reportedError.clear();
        return;
    }
    if (message == m_reportedError)
        return;
    m_reportedError = message;
    emit renderError(message);
}

double ViewportWidget::depthUnderCursor(QPointF position)
{
    const double fallback = m_orbit.distance();
    if (!m_lastFrame)
        return fallback;
    const TrimImage image = readTrimImage();
    const int x = int(std::floor(position.x() * devicePixelRatio()));
    const int y = int(std::floor(position.y() * devicePixelRatio()));
    if (x < 0 || y < 0 || x >= image.width || y >= image.height)
        return fallback;
    const TrimPixel& pixel = image.at(x, y);
    const double depth = pixel.viewDepth;
    return pixel.covered() && std::isfinite(depth) && depth > 0.0 ? depth : fallback;
}

bool ViewportWidget::startObjectDrag(QPointF position)
{
    const std::optional<TrimPixel> pixel = trimPixelAt(position);
    if (!pixel || pixel->objectId < 0 || !std::isfinite(pixel->viewDepth) || !(pixel->viewDepth > 0.0))
        return false; // the background or a cap: the camera orbits as without Ctrl
    m_drag = Drag::MoveObject;
    m_draggedObject = pixel->objectId;
    m_grabDepth = pixel->viewDepth;
    m_lastMouse = position;
    return true;
}

// The ray through the pixel under `position` (the frame's camera and size), at `depth`.
glm::dvec3 ViewportWidget::worldAtDepth(QPointF position, double depth) const
{
    const QSize size = framePixelSize();
    const QPointF device = devicePosition(position);
    const int x = std::clamp(int(std::floor(device.x())), 0, size.width() - 1);
    const int y = std::clamp(int(std::floor(device.y())), 0, size.height() - 1);
    const PixelRay ray = pixelRay(camera(), size.width(), size.height(), x, y);
    return ray.origin + depth * ray.direction;
}

void ViewportWidget::mousePressEvent(QMouseEvent* event)
{
    if (m_drag == Drag::None && m_tool && m_tool->pressed(*event)) {
        m_drag = Drag::Tool;
        event->accept();
        return;
    }
    if (m_drag == Drag::Tool) {
        event->accept(); // a second button during a tool drag changes nothing
        return;
    }
    const bool ctrlLeft = event->button() == Qt::LeftButton && event->modifiers() == Qt::ControlModifier;
    if (ctrlLeft && m_objectDragEnabled && m_drag == Drag::None && startObjectDrag(event->position())) {
        event->accept();
        return;
    }
    const bool shiftLeft = event->button() == Qt::LeftButton && (event->modifiers() & Qt::ShiftModifier);
    if (shiftLeft || event->button() == Qt::RightButton || event->button() == Qt::MiddleButton) {
        m_drag = Drag::Pan;
        m_grabDepth = depthUnderCursor(event->position());
    } else if (event->button() == Qt::LeftButton) {
        m_drag = Drag::Orbit;
    } else {
        QOpenGLWidget::mousePressEvent(event);
        return;
    }
    applyPendingReset();
    m_lastMouse = event->position();
    event->accept();
}

void ViewportWidget::mouseMoveEvent(QMouseEvent* event)
{
    if (m_drag == Drag::Tool) {
        m_tool->moved(*event);
        event->accept();
        return;
    }
    if (m_drag == Drag::None) {
        if (m_tool && event->buttons() == Qt::NoButton)
            m_tool->hovered(event->position());
        QOpenGLWidget::mouseMoveEvent(event);
        return;
    }
    if (m_drag == Drag::MoveObject) {
        const glm::dvec3 moved = worldAtDepth(event->position(), m_grabDepth) - worldAtDepth(m_lastMouse, m_grabDepth);
        m_lastMouse = event->position();
        if (moved != glm::dvec3(0.0))
            emit objectDragged(m_draggedObject, moved);
        event->accept();
        return;
    }
    const QPointF delta = event->position() - m_lastMouse;
    m_lastMouse = event->position();
    if (m_drag == Drag::Orbit)
        m_orbit.orbitByDrag(delta.x(), delta.y(), height());
    else
        m_orbit.pan(delta.x(), delta.y(), height(), m_grabDepth);
    event->accept();
    update();
}

void ViewportWidget::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->buttons() == Qt::NoButton) {
        const Drag ended = m_drag;
        m_drag = Drag::None;
        if (ended == Drag::Tool && m_tool)
            m_tool->released(*event);
        if (ended == Drag::MoveObject)
            emit objectDragFinished(m_draggedObject);
    }
    event->accept();
}

void ViewportWidget::leaveEvent(QEvent* event)
{
    if (m_tool && m_drag == Drag::None)
        m_tool->left();
    QOpenGLWidget::leaveEvent(event);
}

void ViewportWidget::mouseDoubleClickEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton || m_drag == Drag::Tool) {
        QOpenGLWidget::mouseDoubleClickEvent(event);
        return;
    }
    m_drag = Drag::None;
    fitToView();
    event->accept();
}

void ViewportWidget::wheelEvent(QWheelEvent* event)
{
    const double notches = event->angleDelta().y() / kAngleDeltaPerNotch;
    if (notches == 0.0) {
        event->ignore();
        return;
    }
    applyPendingReset();
    const double factor = OrbitController::wheelZoomFactor(notches);
    if (event->modifiers() & Qt::ControlModifier)
        m_orbit.zoomAt(factor, event->position().x(), event->position().y(), width(), height());
    else
        m_orbit.zoom(factor);
    event->accept();
    update();
}

void ViewportWidget::keyPressEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_F && !(event->modifiers() & ~Qt::KeypadModifier)) {
        fitToView();
        event->accept();
        return;
    }
    QOpenGLWidget::keyPressEvent(event);
}

} // namespace trimlab::ui
