#pragma once
/// \file
/// What the interactive view renders, without the widget that shows it
/// (ui/viewport/viewport_widget.h keeps input, the camera and painting):
/// - the view's content kept on the CPU — the scene, object 0's pose, per-vertex colours,
///   the dynamic rules' chain and its shown level, the trim settings and the method
///   parameters — so that a new OpenGL context gets all of it again after a GPU reset;
/// - the renderers of the current context (TrimRenderer, and DynamicTrimRenderer under
///   the dynamic rules), brought up to date before each frame: only what changed is
///   uploaded (a pose, the model matrices, colours, a drag's shown level);
/// - the frame policy (frame_policy.h): which method renders, the memory fallbacks, the
///   CPU still, and what a GPU reset changes;
/// - the record of the last successful frame.
/// Every call that touches the GPU needs the context of initialize() current.

#include "render/dynamic_trim_renderer.h"
#include "render/frame_policy.h"
#include "render/frame_times.h"
#include "render/trim_renderer.h"

#include "core/skinning/skinning_model.h"
#include "core/trim/dynamic_chain.h"

#include <QSize>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

class QOpenGLContext;

namespace trimlab::render {

class GpuSkinning;
class GpuSubdivision;
struct SubdivisionStencils;

/// What the last successful frame was rendered with (for tests, exports and readbacks).
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

    ViewportRenderer();
    ~ViewportRenderer();
    ViewportRenderer(const ViewportRenderer&) = delete;
    ViewportRenderer& operator=(const ViewportRenderer&) = delete;

    // The content, kept across OpenGL contexts.

    /// Shows `scene` (nullptr: nothing): clears the pose, the colours, the dynamic chain
    /// and the last frame, and goes back to the chosen method.
    void setScene(std::shared_ptr<const Scene> scene);
    /// `scene` has the shown scene's objects with the same meshes and other model
    /// matrices: only the matrices are uploaded. Throws std::invalid_argument without a
    /// shown scene or when an object's vertex or triangle count differs.
    void setSceneTransforms(std::shared_ptr<const Scene> scene);
    [[nodiscard]] const std::shared_ptr<const Scene>& scene() const { return m_scene; }
    /// Object 0 at `positions` (#V, object space) from the next frame on. Throws
    /// std::invalid_argument on a vertex count mismatch or without a scene.
    void showPose(const std::vector<glm::vec3>& positions);
    /// Object 0 at pose `pose` of `model` (a skinning of object 0's mesh) from the next
    /// frame on: skinned on the GPU into the scene's buffers (frame/gpu_skinning.h: no
    /// vertex upload, a pose-to-pose chain one step per pose in playback), or — where the
    /// GPU path fails (a shader, memory, a model that does not fit the object), from then
    /// on for this model — uploaded from `positions`, the CPU's skinning of that pose,
    /// which posedScene() and the CPU still show in any case. Throws as showPose, and
    /// std::invalid_argument for a pose beyond the model.
    void showSkinnedPose(std::shared_ptr<const SkinningModel> model, std::size_t pose,
                         const std::vector<glm::vec3>& positions);
    /// Whether the pose of the last frame was skinned on the GPU (showSkinnedPose).
    [[nodiscard]] bool poseSkinnedOnGpu() const { return m_poseOnGpu && m_skinning; }
    /// Object 0, the mesh of the subdivision surface `stencils` were taken from, at the
    /// surface's evaluation at `controlPoints` (#C) from the next frame on: evaluated on
    /// the GPU into the scene's buffers (frame/gpu_subdivision.h: only the control points
    /// are uploaded), or — where the GPU path fails (OpenSubdiv's GL loader or kernel,
    /// memory, stencils that do not fit the object), from then on for these stencils —
    /// uploaded from `positions`, the CPU's evaluation, which posedScene() and the CPU still
    /// show in any case. Throws as showPose, and std::invalid_argument for another number
    /// of control points than the stencils take.
    void showSubdivisionPose(std::shared_ptr<const SubdivisionStencils> stencils,
                             std::vector<glm::dvec3> controlPoints, const std::vector<glm::vec3>& positions);
    /// Whether the pose of the last frame was evaluated on the GPU (showSubdivisionPose).
    [[nodiscard]] bool poseSubdividedOnGpu() const { return m_poseOnGpu && m_subdivision; }
    /// One RGBA8 colour per vertex of the scene (objects in order); empty: the trim
    /// palette. Throws std::invalid_argument on a count mismatch.
    void setVertexColors(std::vector<std::uint32_t> rgba8);
    [[nodiscard]] bool showsVertexColors() const { return !m_vertexColors.empty(); }
    /// The scene as the CPU reference must see it: the pose applied to object 0.
    [[nodiscard]] std::shared_ptr<const Scene> posedScene();

    void setTrimSettings(const TrimSettings& settings) { m_settings = settings; }
    [[nodiscard]] const TrimSettings& trimSettings() const { return m_settings; }
    /// The chosen method (policy().choose()).
    void setMethod(FragmentMethodKind method);
    /// k is clamped to 1..MethodParameters::kMaxK and S to >= 1; back to the chosen method.
    void setMethodParameters(const MethodParameters& parameters);
    [[nodiscard]] const MethodParameters& methodParameters() const { return m_parameters; }

    /// The dynamic rules of `chain` (its last level is the shown frame) from the next frame
    /// on; nullptr: the static rule. A stop after resets in a row is lifted.
    void setDynamicChain(std::shared_ptr<const DynamicChain> chain);
    /// Replaces only the chain's shown level (a drag); ignored without a chain.
    void setDynamicShownLevel(std::shared_ptr<const DynamicChainLevel> level);
    /// The shown level becomes the reference of a new set, `level` is shown (an animation
    /// played forward against its previous pose): the earlier characterizations stay
    /// cached, so the frame characterizes one level instead of the whole history.
    /// Ignored without a chain.
    void appendDynamicLevel(std::shared_ptr<const DynamicChainLevel> level);
    /// Levels of the chain shown, appended ones included (0 without a chain).
    [[nodiscard]] std::size_t dynamicLevelCount() const;
    [[nodiscard]] bool rendersDynamicRules() const { return m_chain != nullptr; }
    /// The chain's shown level as last set (setDynamicShownLevel or the chain's last).
    [[nodiscard]] const DynamicChainLevel* dynamicShownLevel() const;
    /// The dynamic renderer's numbers of the last frame (nullopt for static frames).
    [[nodiscard]] const std::optional<DynamicFrameStats>& lastDynamicStats() const { return m_dynamicStats; }

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
    /// The last successful frame, or nullopt.
    [[nodiscard]] const std::optional<ViewFrame>& lastFrame() const { return m_lastFrame; }
    void forgetLastFrame() { m_lastFrame.reset(); }
    /// `camera` at `size` with `method`: one untimed warm-up frame, then `frames` timed
    /// ones, not shown; afterwards the renderer is back on the effective method.
    MethodMeasurement measure(FragmentMethodKind method, int frames, const Camera& camera, QSize size);

private:
    [[nodiscard]] FrameDemands frameDemands() const;
    void syncGpuScene();
    void uploadPose();
    [[nodiscard]] bool skinPoseOnGpu();
    [[nodiscard]] bool subdividePoseOnGpu();
    void renderFrame(const Camera& camera, QSize size, GLuint framebuffer);
    void renderDynamicFrame(const Camera& camera, QSize size);
    void recordFrame(const Camera& camera, QSize size);

    FramePolicy m_policy;
    std::unique_ptr<TrimRenderer> m_renderer;
    std::unique_ptr<DynamicTrimRenderer> m_dynamic;
    std::shared_ptr<const Scene> m_scene;
    std::shared_ptr<const Scene> m_posedScene; ///< m_scene with the pose applied (cached)
    TrimSettings m_settings;
    MethodParameters m_parameters;
    std::vector<glm::vec3> m_pose;              ///< object 0's positions; empty: the scene's
    std::vector<std::uint32_t> m_vertexColors; ///< empty: the trim palette
    std::shared_ptr<const SkinningModel> m_skinning; ///< m_pose is its pose m_skinnedPose
    std::size_t m_skinnedPose = 0;
    std::unique_ptr<GpuSkinning> m_gpuSkinning;            ///< of m_gpuSkinningModel, this context's
    std::shared_ptr<const SkinningModel> m_gpuSkinningModel;
    bool m_gpuSkinningFailed = false; ///< for m_skinning: upload the CPU's poses
    std::shared_ptr<const SubdivisionStencils> m_subdivision; ///< m_pose is its evaluation at m_controlPoints
    std::vector<glm::dvec3> m_controlPoints;
    std::unique_ptr<GpuSubdivision> m_gpuSubdivision; ///< of m_gpuSubdivisionStencils, this context's
    std::shared_ptr<const SubdivisionStencils> m_gpuSubdivisionStencils;
    bool m_gpuSubdivisionFailed = false; ///< for m_subdivision: upload the CPU's positions
    bool m_poseOnGpu = false;
    bool m_sceneUploaded = false;
    bool m_poseDirty = false;
    bool m_transformsDirty = false; ///< model matrices changed since the upload
    bool m_colorsDirty = false;
    std::shared_ptr<const DynamicChain> m_chain;      ///< nullptr: static rule
    std::shared_ptr<const DynamicChainLevel> m_level; ///< replaces the last level (appended ones included)
    /// Levels after the chain's (appendDynamicLevel); the first m_appendedUploaded are on
    /// the dynamic renderer.
    std::vector<std::shared_ptr<const DynamicChainLevel>> m_appended;
    std::size_t m_appendedUploaded = 0;
    /// The chain's own last level as replaced before a level was appended.
    std::shared_ptr<const DynamicChainLevel> m_chainLastLevel;
    bool m_chainDirty = false;
    bool m_dynamicColorsDirty = false; ///< m_vertexColors not yet on the dynamic renderer
    bool m_levelDirty = false;
    std::optional<DynamicFrameStats> m_dynamicStats;
    std::optional<ViewFrame> m_lastFrame;
};

} // namespace trimlab::render
