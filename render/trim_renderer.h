#pragma once
/// \file
/// Renders a Scene trimmed by a static rule, with an optional clipping plane, through the
/// multi-fragment method the user picked (render/mfr/), into a RenderTarget. Owns every
/// GL object it uses; the caller owns the context and must keep it current across calls
/// and at destruction.

#include "render/frame/frame_counters.h"
#include "render/frame/frame_results.h"
#include "render/gl/context_reset.h"
#include "render/gl/gl_capabilities.h"
#include "render/mfr/fragment_method.h"

#include "core/scene/scene.h"
#include "core/trim/trim_image.h"
#include "core/trim/trim_settings.h"
#include "core/view/camera.h"

#include <QElapsedTimer>
#include <QImage>
#include <QStringList>

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>

class QOpenGLContext;

namespace trimlab::render {

class GpuScene;
class ObjectWindingBuffer;
class RenderTarget;
class ShaderLibrary;

/// What a frame cost and what it found.
struct FrameStats {
    std::uint64_t serial = 0; ///< the renderer's number of the frame (1, 2, …)
    FragmentMethodKind method = FragmentMethodKind::KPlusArray;
    FrameCounts counts;
    MethodStats methodStats;
    /// GL_TIME_ELAPSED of the frame; negative when the driver's answer was implausible
    /// (llvmpipe returns garbage for the first timer query of a context).
    double gpuMilliseconds = 0.0;
    /// Wall-clock time from the start of render() until its results were in: the wait
    /// for the GPU included; when pipelined, until the collection that found them.
    double wallMilliseconds = 0.0;
    /// Wall-clock time of the CPU's work of issuing the frame in render(), the wait for
    /// the GPU's results left out.
    double issueMilliseconds = 0.0;
    double bufferMegabytes = 0.0; ///< method storage + render target + scene buffers
    int width = 0;
    int height = 0;
    int k = 0;
};

/// How a frame classifies its fragments: the static rule of TrimSettings (default), or
/// one level of the dynamic rules' chain (render/dynamic_trim_renderer.h binds the
/// per-pixel state those need).
struct TrimMode {
    bool dynamic = false;
    bool characterize = false; ///< write the characterization instead of stopping at the trim
    int dynamicRule = 3;       ///< DynamicRule as int
    bool referenceIsBase = true;
};

/// The settings need a method that walks all of a pixel's fragments in one pass
/// (MethodInfo::inspection): per-object windings (CSG, collision highlighting), coplanar
/// counts or transparency. Other methods refuse such settings with std::invalid_argument.
[[nodiscard]] bool needsInspectionMethod(const TrimSettings& settings);
/// Why the method `info` cannot render `settings` (under the dynamic rules when
/// `dynamic`), naming the methods to pick instead; nullopt when it can. render() throws
/// this reason; the Render panel shows it on the methods it disables.
[[nodiscard]] std::optional<std::string> methodRefusal(const MethodInfo& info, bool dynamic,
                                                       const TrimSettings& settings);

class TrimRenderer {
public:
    /// `context` must be current. Throws GlUnavailableError if it lacks OpenGL 4.3
    /// features, ShaderBuildError if a shader does not build.
    explicit TrimRenderer(QOpenGLContext& context);
    ~TrimRenderer();
    TrimRenderer(const TrimRenderer&) = delete;
    TrimRenderer& operator=(const TrimRenderer&) = delete;

    /// Uploads `scene` (replacing the previous one). Throws GpuMemoryError or
    /// std::invalid_argument (scene beyond the fragment format's limits).
    void setScene(const Scene& scene);
    /// The uploaded scene's buffers, e.g. to update an animated object's positions or to
    /// show per-vertex colors.
    [[nodiscard]] GpuScene& gpuScene() { return *m_scene; }

    /// Switches the multi-fragment method (its storage is allocated on the next frame).
    void setMethod(FragmentMethodKind method);
    [[nodiscard]] FragmentMethodKind method() const { return m_method->kind(); }
    /// The current method object, e.g. to ask a concrete method (via dynamic_cast) for its
    /// allocation after a frame.
    [[nodiscard]] FragmentMethod& methodObject() { return *m_method; }
    void setParameters(const MethodParameters& parameters);
    [[nodiscard]] const MethodParameters& parameters() const { return m_parameters; }
    /// Shorthand for the k of the parameters, 1..MethodParameters::kMaxK. Default 16.
    void setK(int k);
    [[nodiscard]] int k() const { return m_parameters.k; }
    /// GPU memory the current method would hold at width×height (nullopt: scene-dependent).
    [[nodiscard]] std::optional<std::size_t> estimateMethodBytes(int width, int height) const;

    /// Renders one frame at width×height into the internal render target.
    /// `settings.trimEnabled` must be false for scenes that are not closed oriented
    /// surfaces (the caller knows from the validation report). Throws GpuMemoryError —
    /// before allocating anything when the frame is beyond the driver's texture limits or
    /// the memory budget of the parameters (frame_limits.h); memory_fallback.h says what
    /// to try next —, and std::invalid_argument when the settings ask for what the method
    /// cannot do (CSG, collision or coplanar highlighting with a peeling method or the
    /// two-pass method — the message names the buffer methods to pick instead; clip sets
    /// and capping work with every method; transparency likewise needs a buffer method), for a CSG expression naming an object the
    /// scene lacks, and for collision highlighting in a scene of more than
    /// kMaxCsgOperands objects. Throws GlContextLostError when the GPU was reset during the
    /// frame (gl/context_reset.h): the renderer and everything uploaded to it are gone.
    void render(const Camera& camera, const TrimSettings& settings, int width, int height);
    /// The same with another uploaded scene and a classification mode. Throws
    /// std::invalid_argument when the mode is dynamic and the method cannot run it, or
    /// the settings ask for capping, CSG, highlighting or transparency (static
    /// classification only).
    void render(GpuScene& scene, const TrimMode& mode, const Camera& camera, const TrimSettings& settings, int width,
                int height);
    [[nodiscard]] GlFunctions& gl() { return m_gl; }

    /// Copies the last frame's colors into `framebuffer` (e.g. a QOpenGLWidget's).
    void blitTo(GLuint framebuffer);
    /// The last frame's color image (top row first).
    [[nodiscard]] QImage readColor();
    /// The last frame's per-pixel answers, for comparison with the CPU reference.
    [[nodiscard]] TrimImage readTrimImage();
    /// Per-pixel fragment counts of the last frame (methods that keep them).
    [[nodiscard]] std::optional<PixelOccupancy> readOccupancy();

    /// Frames wait for the GPU (the default: render() returns with the frame's results
    /// in lastStats()), or are pipelined: render() only issues the frame, and its
    /// results arrive a frame or more later through collectFrames() — the CPU prepares
    /// the next frame while the GPU draws this one. Pipelined characterization passes of
    /// the dynamic rules are not timed. Leaving pipelining waits for the pending frames.
    void setPipelined(bool pipelined);
    [[nodiscard]] bool pipelined() const { return m_pipelined; }
    /// Takes the results of the frames the GPU has finished; never waits. True when
    /// lastStats() changed. Throws GlContextLostError after a GPU reset.
    bool collectFrames();
    /// Waits for the results of every frame issued (a readback, a measurement).
    void finishFrames();
    /// Whether an issued frame's results are still to come.
    [[nodiscard]] bool framesPending() const { return !m_pending.empty(); }
    /// The number of the last frame render() issued (0 before the first).
    [[nodiscard]] std::uint64_t lastIssuedFrame() const { return m_serial; }

    /// The newest frame whose results are in (unless pipelined, the frame just rendered).
    [[nodiscard]] const FrameStats& lastStats() const { return m_stats; }
    [[nodiscard]] const GlCapabilities& capabilities() const { return m_capabilities; }
    /// Whether the driver tells this renderer's context about GPU resets
    /// (gl/context_reset.h); without it a reset is seen only if Qt invalidates the context.
    [[nodiscard]] bool detectsContextResets() const { return m_resetWatch.notifies(); }

private:
    /// The defines and buffer the frame's inspection settings need (capping, per-object
    /// windings, coplanar counts); the buffer, or nullptr without per-object windings.
    ObjectWindingBuffer* prepareInspection(const TrimSettings& settings, std::size_t objectCount, int width, int height,
                                           QStringList& defines);

    GlCapabilities m_capabilities; // first: m_gl's initialisation checks it
    GlFunctions& m_gl;
    ContextResetWatch m_resetWatch;
    std::unique_ptr<ShaderLibrary> m_shaders;
    std::unique_ptr<GpuScene> m_scene;
    std::unique_ptr<RenderTarget> m_target;
    std::unique_ptr<FrameCounters> m_counters;
    std::unique_ptr<FragmentMethod> m_method;
    std::unique_ptr<ObjectWindingBuffer> m_objectWindings; // created on first use
    MethodParameters m_parameters;
    /// A timed frame issued and waiting for its results: what the CPU knows of it.
    struct PendingFrame {
        FrameStats stats;
        std::int64_t startNs = 0; ///< render()'s start on m_clock
    };
    /// Fills lastStats() from `results` (oldest first); true when any arrived.
    bool takeResults(const std::vector<FrameResult>& results);

    std::unique_ptr<FrameResultRing> m_results;
    bool m_pipelined = false;
    std::uint64_t m_serial = 0;
    std::deque<PendingFrame> m_pending;
    QElapsedTimer m_clock;
    FrameStats m_stats;
};

} // namespace trimlab::render
