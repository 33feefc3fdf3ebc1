#pragma once
/// \file
/// The 3D view: a QOpenGLWidget that owns the shown content, a ViewportRenderer and an
/// OrbitController. It
/// renders only when something changed (scene, settings, camera, size) — never in a loop
/// — at the widget's device-pixel size, and blits the result into its framebuffer.
/// Painting never waits for the GPU: a frame's statistics arrive a frame or more later
/// (frameRendered()), collected from the event loop; readbacks wait for them.
///
/// Mouse: left drag orbits, right or middle drag (or Shift + left drag) pans, the wheel
/// dollies toward the target (Ctrl + wheel toward the point under the cursor), a double
/// click fits the scene. Keys: F fits the scene. With setObjectDragEnabled, Ctrl + left
/// drag on an object asks to move it in the view plane (objectDragged; the owner moves it). A ViewportTool (setTool, e.g. the brush)
/// is asked first on every press and takes the presses it wants; what it leaves (for the
/// brush: Alt + left drag, right and middle drag) still moves the camera.
///
/// What it shows is the shown content (render/shown_content.h, content()): the document's
/// scene, which the widget sets (setScene, replaceScene, setSceneTransforms — they frame
/// the camera too), and the pose, colour and dynamic-chain layers the features publish
/// into through their render::ContentPublisher. The widget keeps input, the camera and
/// painting, repaints when the content changes, and renders it through its
/// render::ViewportRenderer, which uploads only the layers that changed. Under the
/// dynamic rules (a chain shown) frames render through a DynamicTrimRenderer: the chain's
/// levels are uploaded once, and a drag's replaced shown level keeps the cached
/// characterizations of the earlier sets. An animation passes the bounds of all its poses
/// (setMotionBounds) so that no pose leaves the depth range and Fit frames the motion.
///
/// OpenGL failures (no 4.3 context, a shader that does not build) never crash and never
/// leave a silent black view: the message is painted into the view and emitted once
/// through renderError(). Which method renders, and what a failed frame changes, is
/// decided by render/frame_policy.h; the widget carries it out. Too little GPU memory for
/// the chosen method is not an error: the view renders with the next method and says so
/// through memoryFallback(), or shows the CPU reference as a still image
/// (cpu_still_render.h), rendered off the UI thread. A GPU reset (render/gl/
/// context_reset.h: the renderer reports it after a frame, or Qt marks the context
/// invalid) loses every GL object but nothing of the work: the view re-creates its
/// OpenGL context the way Qt does when a window's graphics device is lost, uploads the
/// scene, pose, colors and dynamic chain again and renders the same frame, and says so
/// through contextLost() — or, for resets in a row, moves on along the fallback chain
/// or stops with a message. Choosing a method, parameters, a scene, a dynamic chain or
/// a size tries again.

#include "ui/viewport/cpu_still_render.h"
#include "ui/viewport/memory_estimate.h"
#include "ui/viewport/viewport_tool.h"

#include "render/gl/gl_debug_log.h"
#include "render/viewport_renderer.h"

#include "core/view/orbit_controller.h"

#include <QImage>
#include <QOpenGLDebugLogger>
#include <QOpenGLWidget>
#include <QPointF>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

class QTimer;

namespace trimlab::ui {

/// What the last successful frame was rendered with (render/viewport_renderer.h).
using ViewportFrame = render::ViewFrame;
/// What ViewportWidget::measureMethod found.
using MethodMeasurement = render::MethodMeasurement;

class ViewportWidget : public QOpenGLWidget {
    Q_OBJECT
public:
    explicit ViewportWidget(QWidget* parent = nullptr);
    ~ViewportWidget() override;

    /// What the view shows: the features publish into it (render/content_publisher.h);
    /// readouts ask it for the shown scene (posedScene).
    [[nodiscard]] const std::shared_ptr<render::ShownContent>& content() const { return m_content; }
    /// Shows `scene` (nullptr: an empty view). The view is reset (reset view) on the next
    /// frame, when the widget's final size is known. The content's pose, colours and
    /// dynamic chain go (they belonged to the previous meshes), and the view bounds become
    /// the scene's bounds.
    void setScene(std::shared_ptr<const Scene> scene);
    /// Shows `scene` in place of the shown one keeping the camera (an object was added
    /// to the scene shown): uploads it, the view bounds become its bounds, the pose, the
    /// colours and the dynamic chain go as by setScene().
    void replaceScene(std::shared_ptr<const Scene> scene);
    /// Shows `scene`, which has the shown scene's objects with the same meshes and differs
    /// only in model matrices (the Scene panel moved an object): only the matrices go to
    /// the GPU (GpuScene::setModelMatrix), the view bounds become the new world bounds and
    /// the camera stays. Throws std::invalid_argument without a shown scene or when an
    /// object or vertex count differs (use replaceScene then).
    void setSceneTransforms(std::shared_ptr<const Scene> scene);
    /// The scene shown (nullptr: none).
    [[nodiscard]] const std::shared_ptr<const Scene>& scene() const { return m_content->scene(); }
    /// The box the camera's depth range must enclose (default: the scene's world bounds):
    /// a design history passes every frame's, so that no frame reaches past the far plane.
    /// Fit and Home still frame the surface as shown. Re-renders; the camera itself is not
    /// moved.
    void setViewBounds(const Bounds& bounds);
    /// The bounds of every pose of an animation: the depth range encloses them (as
    /// setViewBounds), and Fit and Home frame them too, so that a figure walking across
    /// the scene stays in view while it plays. setScene() forgets them.
    void setMotionBounds(const Bounds& bounds);
    /// How the pose of the last static frame reached the GPU: skinned or subdivided there,
    /// or the CPU's positions uploaded.
    [[nodiscard]] render::PoseEvaluation poseEvaluation() const { return m_view.lastPoseEvaluation(); }
    /// The settings to render with. The caller passes trimEnabled = false for scenes that
    /// are not trimmable.
    void setTrimSettings(const TrimSettings& settings);
    /// The multi-fragment method to render with (one of render::fragmentMethods()).
    void setMethod(render::FragmentMethodKind method);
    /// Its parameters; k is clamped to 1..MethodParameters::kMaxK and S to >= 1.
    void setMethodParameters(const render::MethodParameters& parameters);
    /// Shorthand: the k of the parameters.
    void setK(int k);
    [[nodiscard]] const TrimSettings& trimSettings() const { return m_view.trimSettings(); }
    [[nodiscard]] render::FragmentMethodKind method() const { return m_view.policy().chosenMethod(); }
    [[nodiscard]] const render::MethodParameters& methodParameters() const { return m_view.methodParameters(); }
    [[nodiscard]] int k() const { return m_view.methodParameters().k; }
    /// The GPU memory the chosen method would hold at framePixelSize()
    /// (TrimRenderer::estimateMethodBytes); not available before the renderer exists.
    [[nodiscard]] MemoryEstimate memoryEstimate() const;

    /// Renders the current view with `method` (and the chosen parameters) off-screen: one
    /// untimed warm-up frame, then `frames` timed ones, without showing them — to compare
    /// methods on this view. Afterwards the renderer is back on the chosen method and the
    /// view re-renders. Throws what TrimRenderer throws, or std::runtime_error when the
    /// view has nothing to render.
    MethodMeasurement measureMethod(render::FragmentMethodKind method, int frames);

    /// The camera the next frame uses (depth range enclosing the scene).
    [[nodiscard]] Camera camera() const;
    /// Adopts `camera` (see OrbitController::setCamera) and re-renders.
    void setCamera(const Camera& camera);
    /// Frames what is shown (shownBounds) keeping the view direction.
    void fitToView();
    /// Frames what is shown from the default direction (fitCamera's).
    void resetView();
    /// World points beyond the surface that Fit and Home must frame too (a control net);
    /// empty: none.
    void setFramingPoints(std::vector<glm::dvec3> worldPoints);
    /// The bounds of the posed scene and the framing points.
    [[nodiscard]] Bounds shownBounds();
    /// Frames the scene looking along `direction` (eye → target): the view presets
    /// (front looks along −z, top along −y, …).
    void viewAlong(const glm::dvec3& direction);

    /// The size frames are rendered at: the widget size in device pixels.
    [[nodiscard]] QSize framePixelSize() const;
    /// The last successful frame, or nullopt before the first one.
    [[nodiscard]] const std::optional<ViewportFrame>& lastFrame() const { return m_view.lastFrame(); }
    /// The last frame's color image (top row first); null without a frame.
    [[nodiscard]] QImage readColorImage();
    /// The last frame's per-pixel answers; empty without a frame.
    [[nodiscard]] TrimImage readTrimImage();

    /// Why no viewport can render on this platform: "" when an OpenGL 4.3 core context
    /// with TrimLab's requirements can be created, else the reason. Creates and destroys
    /// an offscreen context; call before showing any ViewportWidget. (Without any OpenGL,
    /// Qt cannot even composite a window that contains a QOpenGLWidget, so such a window
    /// must not contain one.)
    [[nodiscard]] static QString openGlProblem();
    /// Marks the view as unable to render for `reason` (shown by errorMessage()); used
    /// when openGlProblem() is not empty and the widget is therefore never shown.
    void setUnavailable(const QString& reason);

    /// Whether Ctrl + left drag on an object reports objectDragged() instead of orbiting
    /// (default off: the owner turns it on while objects may be moved).
    void setObjectDragEnabled(bool enabled) { m_objectDragEnabled = enabled; }
    [[nodiscard]] bool objectDragEnabled() const { return m_objectDragEnabled; }

    /// The mouse tool asked first on every press (nullptr: none). Not owned; the tool
    /// must outlive the viewport or be reset first. Turns on hover tracking.
    void setTool(ViewportTool* tool);
    /// The tooltip without a tool: how the mouse and keys move the camera.
    [[nodiscard]] static QString cameraHelp();
    /// The tool set last (nullptr: none).
    [[nodiscard]] ViewportTool* tool() const { return m_tool; }
    /// `tool` can work (`usable`: it has something to edit) or cannot: it becomes the
    /// tool when the view has none, and stops being it when it cannot work, leaving
    /// another tool that holds the view alone either way.
    void offerTool(ViewportTool* tool, bool usable);

    /// The dynamic renderer's numbers of the last frame (nullopt for static frames).
    [[nodiscard]] const std::optional<render::DynamicFrameStats>& lastDynamicStats() const
    {
        return m_view.lastDynamicStats();
    }

    /// The last frame's answer at the pixel under the logical widget position `position`
    /// (nullopt without a frame or outside it). The trim image is read back once per frame
    /// and kept until the next one, so hovering costs no readback per mouse move.
    [[nodiscard]] std::optional<TrimPixel> trimPixelAt(QPointF position);
    /// `position` (logical widget coordinates) in the frame's device pixels.
    [[nodiscard]] QPointF devicePosition(QPointF position) const { return position * devicePixelRatio(); }

    /// The OpenGL context's capabilities once the renderer exists.
    [[nodiscard]] std::optional<render::GlCapabilities> capabilities() const;
    /// Why the view cannot render ("" when it can).
    [[nodiscard]] const QString& errorMessage() const { return m_error; }
    /// The method frames actually use: the chosen one, or its memory fallback.
    [[nodiscard]] render::FragmentMethodKind effectiveMethod() const { return m_view.policy().effectiveMethod(); }
    /// True while the view shows the CPU reference because no GPU method fits.
    [[nodiscard]] bool showsCpuStill() const { return m_view.policy().showsCpuStill(); }
    /// The CPU reference image shown in that mode (null before it is ready).
    [[nodiscard]] QImage cpuStillImage() const;

    /// Recovers from a GPU reset that `reason` describes (what the driver said): drops the
    /// last frame, reports contextLost() — or, for the second reset in a row without a
    /// frame between, falls back to the next method (memoryFallback()) — and re-creates the
    /// context from the event loop. paintGL() calls it when a frame reports the reset.
    void recoverFromContextLoss(const QString& reason);
    /// How many OpenGL contexts the view has initialized (1 after the first show; each
    /// recovery adds one).
    [[nodiscard]] int contextsInitialized() const { return m_contextsInitialized; }

signals:
    /// When a successful frame's results arrived from the GPU (frames are pipelined: a
    /// frame or more after it was painted; lastFrame() is then that frame).
    void frameRendered(const trimlab::render::FrameStats& stats);
    /// Once per distinct failure (renderer creation, scene upload or a frame).
    void renderError(const QString& message);
    /// The frame size in device pixels changed.
    void framePixelSizeChanged(QSize size);
    /// The chosen method ran out of GPU memory (or its frames reset the GPU twice in a
    /// row): `message` says why and what is shown instead (another method, or the CPU
    /// reference).
    void memoryFallback(const QString& message);
    /// The GPU was reset and the view re-created its context: `message` says what happened
    /// and that the scene was uploaded again.
    void contextLost(const QString& message);
    /// Ctrl + left drag on object `object` (setObjectDragEnabled): the cursor moved the
    /// grabbed point by `worldDelta` (world units, in the view plane at the grabbed
    /// point's depth) since the previous report.
    void objectDragged(int object, const glm::dvec3& worldDelta);
    /// That drag ended (the button went up).
    void objectDragFinished(int object);

protected:
    void initializeGL() override;
    void resizeGL(int width, int height) override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void leaveEvent(QEvent* event) override;

private:
    enum class Drag { None, Orbit, Pan, Tool, MoveObject };

    void releaseGl();
    void recreateContext();
    void applyPendingReset();
    void applyMethod();
    void renderFrame();
    /// Takes the frame results the GPU has delivered (never waits) and reports them;
    /// polled by m_resultPoll while results are pending.
    void collectFrameResults();
    /// frameRendered() for lastFrame() unless it was reported; polls while more are due.
    void reportArrivedFrame();
    /// Waits for the pending frames' results, so that the render target and lastFrame()
    /// agree (the context must be current). False after a GPU reset (then handled).
    bool finishFrames();
    void applyRecovery(const render::FrameRecovery& recovery);
    void paintCpuStill();
    void clearToBackground();
    void paintMessage(const QString& text);
    void setError(const QString& message);
    [[nodiscard]] double aspect() const;
    [[nodiscard]] double depthUnderCursor(QPointF position);
    /// Starts a Ctrl + left drag of the object under `position`; false when none is there.
    bool startObjectDrag(QPointF position);
    /// The world point at view depth `depth` under the logical position `position`.
    [[nodiscard]] glm::dvec3 worldAtDepth(QPointF position, double depth) const;

    OrbitController m_orbit;
    std::shared_ptr<render::ShownContent> m_content; ///< what is shown
    /// The renderers of the current context, the frame policy, the last frame.
    render::ViewportRenderer m_view;
    render::ContentSubscription m_repaint; ///< a change of the content repaints
    bool m_resetPending = false;
    std::vector<glm::dvec3> m_framingPoints; ///< setFramingPoints
    std::optional<Bounds> m_motionBounds;    ///< setMotionBounds; cleared by setScene
    QString m_error;
    QString m_reportedError;
    ViewportTool* m_tool = nullptr;
    TrimImage m_trimCache;                          ///< the last frame's trim image once read (empty: not read)
    int m_contextsInitialized = 0;                  ///< initializeGL() calls
    std::unique_ptr<QOpenGLDebugLogger> m_debugLog; ///< with TRIMLAB_GL_DEBUG only (render/gl/gl_debug_log.h)
    CpuStillRender* m_cpuStill = nullptr;
    QTimer* m_resultPoll = nullptr;    ///< runs while frame results are pending
    std::uint64_t m_reportedFrame = 0; ///< the serial of the last frame frameRendered() reported
    Drag m_drag = Drag::None;
    QPointF m_lastMouse;
    double m_grabDepth = 0.0;
    bool m_objectDragEnabled = false;
    int m_draggedObject = -1;
};

} // namespace trimlab::ui
