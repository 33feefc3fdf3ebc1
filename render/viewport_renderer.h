#pragma once
/// \file
/// What the interactive view renders, without the widget that shows it
/// (ui/viewport/viewport_widget.h keeps input, the camera and painting):
/// - the shown content (shown_content.h: the scene, object 0's pose, per-vertex colours,
///   the dynamic rules' chain), which features publish into and this renderer reads: a
///   layer is uploaded when its version differs from the one uploaded last — a pose, the
///   model matrices, colours, a drag's shown level, appended levels — and every layer
///   again in a new OpenGL context after a GPU reset;
/// - the render choices (trim settings, method, parameters), kept across contexts too;
/// - the renderers of the current context (TrimRenderer, and DynamicTrimRenderer under
///   the dynamic rules), and one GPU pose evaluator (gpu_pose_evaluator.h) for skinned
///   poses and subdivision surfaces alike;
/// - the frame policy (frame_policy.h): which method renders, the memory fallbacks, the
///   CPU still, and what a GPU reset changes (a new scene goes back to the chosen method,
///   a new dynamic chain lifts a stop);
/// - the record of the last successful frame (gone with a new scene).
/// Frames are pipelined (TrimRenderer::setPipelined): render() issues and shows a frame
/// without waiting for the GPU, and the frame becomes lastFrame() when its results
/// arrive — collectFrames() (never waits) or finishFrames() (waits: readbacks, tests).
/// Every call that touches the GPU needs the context of initialize() current.

#include "render/dynamic_trim_renderer.h"
#include "render/frame_policy.h"
#include "render/frame_times.h"
#include "render/gpu_pose_evaluator.h"
#include "render/shown_content.h"
#include "render/trim_renderer.h"

#include <QSize>

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

class QOpenGLContext;

namespace trimlab::render {

/// What a successful frame was rendered with and what it found (for the status bar,
/// tests, exports and readbacks).
struct ViewFrame {
    Camera camera;
    TrimSettings settings;
    int k = 0;
    MethodParameters parameters; ///< the method is stats.method
    QSize pixelSize;             ///< device pixels, as passed to TrimRenderer::render
    FrameStats stats;
    /// When the frame lost fragments (overflowed or lost > 0) and the method keeps
    /// per-pixel counts: the largest count (capped at k by methods that count only what
    /// they hold). nullopt otherwise.
    std::optional<std::uint32_t> largestPixelCount;
    /// The scene as rendered (objects and model matrices), e.g. for the CPU reference.
    std::shared_ptr<const Scene> scene;
    /// The dynamic renderer's numbers of the frame (nullopt for static frames). The
    /// characterization passes of frames shown after the previous record but superseded
    /// before their results arrived count here too: the work since that record.
    std::optional<DynamicFrameStats> dynamicStats;
};

/// What ViewportRenderer::measure found.
struct MethodMeasurement {
    FrameTimes times;
    FrameStats lastStats;
};

class ViewportRenderer {
public:
    /// Receives a notice for the user: a method replaced by its fallback, or the CPU still.
    using Notify = std::function<void(const std::string& notice)>;

    /// Renders what `content` shows.
    explicit ViewportRenderer(std::shared_ptr<ShownContent> content);
    ~ViewportRenderer();
    ViewportRenderer(const ViewportRenderer&) = delete;
    ViewportRenderer& operator=(const ViewportRenderer&) = delete;

    [[nodiscard]] const std::shared_ptr<ShownContent>& content() const { return m_content; }
    /// How the pose of the last static frame reached the GPU (Uploaded without a pose).
    [[nodiscard]] PoseEvaluation lastPoseEvaluation() const { return m_poseEvaluation; }

    // The render choices, kept across OpenGL contexts.

    void setTrimSettings(const TrimSettings& settings) { m_settings = settings; }
    [[nodiscard]] const TrimSettings& trimSettings() const { return m_settings; }
    /// The chosen method (policy().choose()).
    void setMethod(FragmentMethodKind method);
    /// k is clamped to 1..MethodParameters::kMaxK and S to >= 1; back to the chosen method.
    void setMethodParameters(const MethodParameters& parameters);
    [[nodiscard]] const MethodParameters& methodParameters() const { return m_parameters; }

    /// The dynamic renderer's numbers of lastFrame() (nullopt for static frames and
    /// without a frame).
    [[nodiscard]] const std::optional<DynamicFrameStats>& lastDynamicStats() const;

    [[nodiscard]] const FramePolicy& policy() const { return m_policy; }
    /// Something changed that may let the chosen method fit again (the view size).
    void resetFallback() { m_policy.reset(); }

    // The OpenGL context.

    /// Creates the renderer in `context` (current), on the effective method; the content
    /// is uploaded at the next frame. Throws GlError (missing OpenGL features).
    void initialize(QOpenGLContext& context);
    /// Drops every GL object (the context is about to go), keeping the content.
    void release();
    [[nodiscard]] bool hasRenderer() const { return m_renderer != nullptr; }
    /// The renderer of the current context (hasRenderer() must be true).
    [[nodiscard]] TrimRenderer& renderer() { return *m_renderer; }
    [[nodiscard]] const TrimRenderer& renderer() const { return *m_renderer; }
    /// Hands the effective method and parameters to the renderer now, so that its memory
    /// estimate answers for them before anything is allocated.
    void applyMethod();

    // Frames.

    /// Renders `camera` at `size` and blits it into `framebuffer`, walking the memory
    /// fallback chain when the GPU runs out of memory (each step's notice to `notify`); a
    /// frame that succeeds ends a run of GPU resets.
    /// Returns false when no GPU method is left: show the CPU still (policy()). Throws
    /// GlContextLostError (a GPU reset: call contextLost()), GpuMemoryError when nothing
    /// fits under the dynamic rules, GlError, std::invalid_argument (e.g. a method that
    /// cannot run the dynamic rules).
    bool render(const Camera& camera, QSize size, GLuint framebuffer, const Notify& notify);
    /// A GPU reset with `reason`: the policy's decision (frame_policy.h); the last frame
    /// is gone.
    [[nodiscard]] FrameRecovery contextLost(const std::string& reason);
    /// The newest successful frame whose results have arrived, or nullopt. The image of
    /// the render target may be of a newer frame until finishFrames().
    [[nodiscard]] const std::optional<ViewFrame>& lastFrame() const { return m_lastFrame; }
    /// Drops the frame record and the frames whose results are still to come.
    void forgetLastFrame();
    /// Takes the results the GPU has delivered; never waits. True when lastFrame()
    /// changed. Throws GlContextLostError after a GPU reset.
    bool collectFrames();
    /// Waits for every issued frame's results: then lastFrame() is the frame the render
    /// target holds. Throws GlContextLostError after a GPU reset.
    void finishFrames();
    /// Whether a frame was issued whose results have not arrived yet.
    [[nodiscard]] bool framesPending() const { return !m_issued.empty(); }
    /// `camera` at `size` with `method`: one untimed warm-up frame, then `frames` timed
    /// ones, not shown; afterwards the renderer is back on the effective method.
    MethodMeasurement measure(FragmentMethodKind method, int frames, const Camera& camera, QSize size);

private:
    /// What this context holds of the content: the versions last uploaded (0: nothing).
    struct Uploaded {
        std::uint64_t meshes = 0;
        std::uint64_t geometry = 0;
        std::uint64_t pose = 0;
        std::uint64_t colors = 0;
        bool posed = false; ///< object 0 holds a pose, not the scene's positions
        std::uint64_t chainId = 0;
        /// The dynamic renderer's levels, oldest first (of chainId).
        std::vector<std::shared_ptr<const DynamicChainLevel>> levels;
        std::uint64_t dynamicColors = 0;
    };
    /// The GPU pose evaluator of the current context and the source it is for.
    struct GpuPose {
        std::shared_ptr<const void> source;
        std::unique_ptr<GpuPoseEvaluator> evaluator; ///< this context's
        bool failed = false;                         ///< the source's evaluator failed: upload the CPU's positions
    };

    void contentChanged(ShownLayer layer);
    /// Frames render the dynamic rules: a chain is shown and trimming is on.
    [[nodiscard]] bool dynamicFrames() const { return m_content->chain() && m_settings.trimEnabled; }
    [[nodiscard]] FrameDemands frameDemands() const;
    void syncGeometry();
    void syncPose();
    void syncColors();
    void syncChain();
    void syncDynamicColors();
    [[nodiscard]] bool evaluatePoseOnGpu(const ShownPose& pose);
    void renderFrame(const Camera& camera, QSize size, GLuint framebuffer);
    void renderDynamicFrame(const Camera& camera, QSize size);
    /// Keeps the frame just issued until its results arrive.
    void recordFrame(const Camera& camera, QSize size);
    /// The issued frame whose results lastStats() holds becomes lastFrame(); true if one did.
    bool adoptArrivedFrame();

    std::shared_ptr<ShownContent> m_content;
    ContentSubscription m_subscription;
    FramePolicy m_policy;
    std::unique_ptr<TrimRenderer> m_renderer;
    std::unique_ptr<DynamicTrimRenderer> m_dynamic;
    TrimSettings m_settings;
    MethodParameters m_parameters;
    Uploaded m_uploaded;
    GpuPose m_gpuPose;
    PoseEvaluation m_poseEvaluation = PoseEvaluation::Uploaded;
    std::uint64_t m_meshesSeen = 0;                  ///< the mesh version the policy and frame record last heard of
    std::uint64_t m_chainSeen = 0;                   ///< the chain id the policy last heard of
    std::optional<DynamicFrameStats> m_dynamicStats; ///< of the frame being issued
    std::optional<ViewFrame> m_lastFrame;
    std::deque<ViewFrame> m_issued; ///< shown frames waiting for their results, oldest first
};

} // namespace trimlab::render
