#include "ui/viewport/viewport_widget.h"

#include "render/gl/context_reset.h"
#include "render/gl/gl_error.h"
#include "render/gl/offscreen_gl_context.h"
#include "render/gl/wide_vector_state.h"

#include "core/trim/trim_shading.h"

#include <QCoreApplication>
#include <QEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QTimer>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace trimlab::ui {

namespace {

// "a · b · c" as one gesture per line: a plain-text tooltip is never wrapped, and all
// gestures on one line were wider than the screen.
QString helpLines(const QString& help)
{
    return help.split(QStringLiteral(" · ")).join(QLatin1Char('\n'));
}

/// Pixels of margin around the message painted into the view.
constexpr int kMessageMargin = 24;
/// QWheelEvent::angleDelta of one wheel notch (15° in eighths of a degree).
constexpr double kAngleDeltaPerNotch = 120.0;

} // namespace

ViewportWidget::ViewportWidget(QWidget* parent)
    : QOpenGLWidget(parent),
      m_content(std::make_shared<render::ShownContent>()),
      m_view(m_content),
      m_repaint(m_content->subscribe([this](render::ShownLayer) { update(); })),
      m_cpuStill(new CpuStillRender(this)),
      m_resultPoll(new QTimer(this))
{
    // Often enough for a frame at hundreds of frames per second, rarely enough to leave
    // the CPU to the frames themselves.
    m_resultPoll->setInterval(2);
    connect(m_resultPoll, &QTimer::timeout, this, &ViewportWidget::collectFrameResults);
    connect(m_cpuStill, &CpuStillRender::ready, this, qOverload<>(&ViewportWidget::update));
    connect(m_cpuStill, &CpuStillRender::failed, this, [this](const QString& message) {
        setError(tr("Neither the GPU nor the CPU reference could render this view: %1").arg(message));
        update();
    });
    // Qt's composition of the frame calls the driver after paintGL (wide_vector_state.h).
    connect(this, &QOpenGLWidget::frameSwapped, this, [] { render::leaveWideVectorState(); });
    setFormat(render::OffscreenGlContext::requestedFormat());
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(160, 120);
    setToolTip(helpLines(cameraHelp()));
}

QString ViewportWidget::cameraHelp()
{
    return tr("Left drag: orbit · Right/middle or Shift+left drag: pan · Wheel: zoom (Ctrl: toward the cursor) · "
              "Double click or F: fit · Ctrl+left drag on an object: move it (when the Scene panel allows)");
}

ViewportWidget::~ViewportWidget()
{
    releaseGl();
}

void ViewportWidget::setScene(std::shared_ptr<const Scene> scene)
{
    m_orbit.setSceneBounds(scene ? scene->worldBounds() : Bounds{});
    m_motionBounds.reset(); // they were the previous scene's poses
    m_content->setScene(std::move(scene));
    m_resetPending = true;
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
    m_content->setSceneTransforms(scene);
    m_orbit.setSceneBounds(scene->worldBounds()); // the depth range must enclose the moved object
    update();
}

void ViewportWidget::setTool(ViewportTool* tool)
{
    m_tool = tool;
    setToolTip(helpLines(tool ? tool->mouseHelp() : cameraHelp())); // what the mouse does now
    setMouseTracking(tool != nullptr); // hover feedback (the brush's region) needs moves without buttons
    if (m_drag == Drag::Tool)
        m_drag = Drag::None;
}

void ViewportWidget::offerTool(ViewportTool* tool, bool usable)
{
    if (usable && !m_tool)
        setTool(tool);
    else if (!usable && m_tool == tool)
        setTool(nullptr);
}

std::optional<TrimPixel> ViewportWidget::trimPixelAt(QPointF position)
{
    if (!m_view.lastFrame())
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

void ViewportWidget::setMotionBounds(const Bounds& bounds)
{
    m_motionBounds = bounds;
    setViewBounds(bounds);
}

void ViewportWidget::setTrimSettings(const TrimSettings& settings)
{
    m_view.setTrimSettings(settings);
    update();
}

void ViewportWidget::setMethod(render::FragmentMethodKind method)
{
    m_view.setMethod(method);
    applyMethod();
    update();
}

void ViewportWidget::setMethodParameters(const render::MethodParameters& parameters)
{
    m_view.setMethodParameters(parameters);
    applyMethod();
    update();
}

void ViewportWidget::setK(int k)
{
    render::MethodParameters parameters = m_view.methodParameters();
    parameters.k = k;
    setMethodParameters(parameters);
}

// Hands the choice to the renderer at once (its storage follows on the next frame), so
// memoryEstimate() answers for it before anything is allocated.
void ViewportWidget::applyMethod()
{
    if (!m_view.hasRenderer())
        return;
    makeCurrent(); // replacing the method object releases its GL storage
    try {
        m_view.applyMethod();
    } catch (const std::exception& e) {
        setError(tr("The method could not be set up: %1").arg(QString::fromStdString(e.what())));
    }
    doneCurrent();
}

MemoryEstimate ViewportWidget::memoryEstimate() const
{
    if (!m_view.hasRenderer())
        return {};
    const QSize size = framePixelSize();
    return {true, m_view.renderer().estimateMethodBytes(size.width(), size.height()), size};
}

MethodMeasurement ViewportWidget::measureMethod(render::FragmentMethodKind method, int frames)
{
    if (!m_view.hasRenderer())
        throw std::runtime_error(m_error.isEmpty() ? "OpenGL is not available." : m_error.toStdString());
    if (!m_content->scene() || m_content->scene()->empty())
        throw std::runtime_error("There is no scene to render.");
    makeCurrent();
    applyPendingReset();
    try {
        const MethodMeasurement result = m_view.measure(method, frames, m_orbit.camera(), framePixelSize());
        doneCurrent();
        update();
        return result;
    } catch (...) {
        doneCurrent();
        update();
        throw;
    }
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
    m_orbit.frame(shownBounds(), aspect());
    m_resetPending = false;
}

void ViewportWidget::setFramingPoints(std::vector<glm::dvec3> worldPoints)
{
    m_framingPoints = std::move(worldPoints);
}

// What Home and Fit frame: the surface as shown now (the pose, not every frame of the
// history the depth range must hold, so Home frames a mesh the same way whatever was
// drawn before), the points drawn over it (a control net reaches past its surface) and
// an animation's every pose (a walk leaves the first pose's box).
Bounds ViewportWidget::shownBounds()
{
    Bounds bounds;
    if (const std::shared_ptr<const Scene> posed = m_content->posedScene())
        bounds = posed->worldBounds();
    for (const glm::dvec3& p : m_framingPoints)
        bounds.extend(p);
    if (m_motionBounds && m_motionBounds->valid())
        bounds.extend(*m_motionBounds);
    return bounds;
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
    m_orbit.frame(shownBounds(), aspect(), m_orbit.viewDirection());
    update();
}

void ViewportWidget::resetView()
{
    m_orbit.frame(shownBounds(), aspect());
    m_resetPending = false;
    update();
}

void ViewportWidget::viewAlong(const glm::dvec3& direction)
{
    m_orbit.frame(shownBounds(), aspect(), direction);
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
    if (!m_view.hasRenderer())
        return std::nullopt;
    return m_view.renderer().capabilities();
}

QImage ViewportWidget::readColorImage()
{
    if (!m_view.hasRenderer() || (!m_view.lastFrame() && !m_view.framesPending()))
        return {};
    makeCurrent();
    QImage image = finishFrames() && m_view.lastFrame() ? m_view.renderer().readColor() : QImage();
    doneCurrent();
    return image;
}

TrimImage ViewportWidget::readTrimImage()
{
    if (!m_view.hasRenderer() || (!m_view.lastFrame() && !m_view.framesPending()))
        return {};
    makeCurrent();
    TrimImage image = finishFrames() && m_view.lastFrame() ? m_view.renderer().readTrimImage() : TrimImage();
    doneCurrent();
    return image;
}

bool ViewportWidget::finishFrames()
{
    try {
        m_view.finishFrames();
    } catch (const render::GlContextLostError& e) {
        recoverFromContextLoss(QString::fromStdString(e.what()));
        return false;
    }
    if (m_view.lastFrame() && m_view.lastFrame()->stats.serial != m_reportedFrame)
        QTimer::singleShot(0, this, &ViewportWidget::reportArrivedFrame); // not from inside a readback
    return true;
}

void ViewportWidget::collectFrameResults()
{
    if (!m_view.hasRenderer() || !m_view.framesPending()) {
        reportArrivedFrame();
        return;
    }
    makeCurrent();
    try {
        (void)m_view.collectFrames();
    } catch (const render::GlContextLostError& e) {
        doneCurrent();
        m_resultPoll->stop();
        recoverFromContextLoss(QString::fromStdString(e.what()));
        return;
    }
    doneCurrent();
    reportArrivedFrame();
}

void ViewportWidget::reportArrivedFrame()
{
    const auto& frame = m_view.lastFrame();
    if (frame && frame->stats.serial != m_reportedFrame) {
        m_reportedFrame = frame->stats.serial;
        emit frameRendered(frame->stats);
    }
    if (m_view.hasRenderer() && m_view.framesPending())
        m_resultPoll->start();
    else
        m_resultPoll->stop();
}

void ViewportWidget::initializeGL()
{
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &ViewportWidget::releaseGl, Qt::UniqueConnection);
    ++m_contextsInitialized;
    m_debugLog = render::startGlDebugLog(*context()); // TRIMLAB_GL_DEBUG only
    try {
        m_view.initialize(*context());
        setError({});
    } catch (const render::GlError& e) {
        setError(QString::fromStdString(e.what()));
    } catch (const std::exception& e) {
        setError(tr("The renderer could not start: %1").arg(QString::fromStdString(e.what())));
    }
}

void ViewportWidget::releaseGl()
{
    if (!m_view.hasRenderer() && !m_debugLog)
        return;
    makeCurrent();
    if (m_view.hasRenderer())
        m_view.release();
    m_debugLog.reset();
    doneCurrent();
}

void ViewportWidget::recoverFromContextLoss(const QString& reason)
{
    m_trimCache = {};
    applyRecovery(m_view.contextLost(reason.toStdString()));
    QMetaObject::invokeMethod(this, &ViewportWidget::recreateContext, Qt::QueuedConnection);
}

// What the frame policy decided after a GPU reset: a notice, or the stop's message.
void ViewportWidget::applyRecovery(const render::FrameRecovery& recovery)
{
    const QString message = QString::fromStdString(recovery.message);
    switch (recovery.action) {
    case render::FrameRecovery::Action::Recreate:
        emit contextLost(message);
        break;
    case render::FrameRecovery::Action::OtherMethod:
    case render::FrameRecovery::Action::CpuStill:
        emit memoryFallback(message);
        break;
    case render::FrameRecovery::Action::Stop:
    case render::FrameRecovery::Action::Refuse:
        setError(message);
        break;
    }
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
    m_view.resetFallback(); // the chosen method may fit the new size
    emit framePixelSizeChanged(framePixelSize());
}

void ViewportWidget::paintGL()
{
    const render::WideVectorStateScope wideVectorState;  // what follows a frame runs on the CPU again
    if (m_view.hasRenderer() && !context()->isValid()) { // Qt saw the reset first (platforms with reset notification)
        clearToBackground();
        recoverFromContextLoss(QString::fromStdString(render::contextResetMessage(render::ContextReset::Unknown)));
        return;
    }
    if (!m_view.hasRenderer() || m_view.policy().stopped()) {
        clearToBackground();
        paintMessage(m_error.isEmpty() ? tr("OpenGL is not available.") : m_error);
        return;
    }
    if (!m_content->scene() || m_content->scene()->empty()) {
        clearToBackground();
        paintMessage(tr("No scene. Open a mesh with File ▸ Open… or drop a mesh file here."));
        return;
    }
    if (m_view.policy().showsCpuStill()) {
        paintCpuStill();
        return;
    }
    renderFrame();
}

// One frame through the renderer (render/viewport_renderer.h), which walks the memory
// fallbacks; what is left to the widget is telling the user and painting.
void ViewportWidget::renderFrame()
{
    bool rendered = false;
    try {
        applyPendingReset();
        const auto notify = [this](const std::string& notice) { emit memoryFallback(QString::fromStdString(notice)); };
        rendered = m_view.render(m_orbit.camera(), framePixelSize(), defaultFramebufferObject(), notify);
        m_trimCache = TrimImage(); // read again on demand: the frame changed
        if (!rendered) {
            paintCpuStill();
            return;
        }
        setError({});
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
        m_view.forgetLastFrame();
        clearToBackground();
        paintMessage(m_error);
        return;
    }
    reportArrivedFrame();
}

QImage ViewportWidget::cpuStillImage() const
{
    return m_view.policy().showsCpuStill() && m_cpuStill->shown() ? m_cpuStill->image() : QImage();
}

// The CPU reference of the current view, drawn when ready; the previous still (or a note)
// meanwhile.
void ViewportWidget::paintCpuStill()
{
    applyPendingReset();
    const std::shared_ptr<const Scene> scene = m_content->posedScene();
    const CpuStillRender::Request request{scene, m_orbit.camera(), m_view.trimSettings(), framePixelSize()};
    m_cpuStill->request(request);
    clearToBackground();
    QPainter painter(this);
    if (m_cpuStill->shown() && m_cpuStill->shown()->scene == scene)
        painter.drawImage(rect(), m_cpuStill->image());
    painter.setPen(QColor(235, 235, 235));
    const bool current = m_cpuStill->shown() && m_cpuStill->shown()->sameView(request);
    painter.drawText(rect().adjusted(kMessageMargin, kMessageMargin, -kMessageMargin, -kMessageMargin),
                     Qt::AlignTop | Qt::AlignLeft,
                     current ? tr("CPU reference (no GPU method fits this view)") : tr("Rendering on the CPU…"));
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
    if (!m_view.lastFrame())
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
