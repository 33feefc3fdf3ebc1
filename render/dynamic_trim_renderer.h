#pragma once
/// \file
/// Renders a frame under the dynamic rules (thesis 8.1.2, Algorithms 8.11–8.13) through
/// the TrimRenderer's current buffer method. Every level of the DynamicChain is uploaded
/// as a scene of frame-classed objects; levels before the last are rendered once per view
/// in characterize mode, each producing the per-pixel partition characterization bit
/// vector (256 layers) the next level takes as its reference; the last level is the shown
/// frame. While the view and the earlier levels stay the same (a designer dragging the
/// brush), a frame costs one pass over the reference and current geometry. A history that
/// grows by a frame (an animation played forward against its previous pose: appendLevel)
/// costs one characterization pass more — the classification is carried from pose to
/// pose as Algorithms 8.11–8.13 carry it, instead of re-running every earlier level.

#include "render/gl/gl_objects.h"
#include "render/trim_renderer.h"

#include "core/trim/dynamic_chain.h"

#include <memory>
#include <vector>

namespace trimlab::render {

class GpuScene;

struct DynamicFrameStats {
    int levels = 0;              ///< sets in the chain
    int characterizedLevels = 0; ///< characterization passes this frame ran (0 when cached)
    double characterizeMilliseconds = 0.0;
    double frameMilliseconds = 0.0; ///< the shown level's wall-clock time
};

class DynamicTrimRenderer {
public:
    /// `renderer`'s context must be current now, at every call and at destruction.
    explicit DynamicTrimRenderer(TrimRenderer& renderer);
    ~DynamicTrimRenderer();
    DynamicTrimRenderer(const DynamicTrimRenderer&) = delete;
    DynamicTrimRenderer& operator=(const DynamicTrimRenderer&) = delete;

    /// Uploads every level; the characterizations are rebuilt at the next render.
    void setChain(const DynamicChain& chain);
    /// Replaces only the shown (last) level, keeping the cached characterizations: the
    /// brush moved the current frame within the same set.
    void setShownLevel(const DynamicChainLevel& level);
    /// The shown level becomes the reference of a new set and `level` (whose reference
    /// frame is the shown frame) is shown: the chain is the one setChain would take with
    /// `level` appended, and renders the same image, but the earlier characterizations
    /// stay cached, so the next render (same view) characterizes one level. Throws
    /// std::invalid_argument without a chain.
    void appendLevel(const DynamicChainLevel& level);
    [[nodiscard]] int levelCount() const { return int(m_levels.size()); }
    /// Per-vertex colors of the designed mesh (one per mesh vertex, RGBA8 as
    /// GpuScene::setVertexColors takes them) shown instead of the trim palette on the shown
    /// level, e.g. the brush's region; empty: back to the palette. Kept across
    /// setShownLevel and setChain until changed. Throws std::invalid_argument on a count
    /// mismatch.
    void setShownVertexColors(std::vector<std::uint32_t> rgba8);

    /// Renders the last level into the TrimRenderer's target (read it back there).
    /// Throws std::invalid_argument when the method cannot run dynamic rules or no chain
    /// is set, GpuMemoryError when the per-pixel state does not fit.
    void render(const Camera& camera, const TrimSettings& settings, int width, int height);

    [[nodiscard]] const DynamicFrameStats& lastStats() const { return m_stats; }
    /// Bytes of the per-pixel dynamic state and bit vectors.
    [[nodiscard]] std::size_t memoryBytes() const { return m_bytes; }

private:
    void resizeState(int width, int height);
    void clearState(int width, int height);
    void characterizeLevels(const Camera& camera, const TrimSettings& settings, int width, int height);
    [[nodiscard]] bool viewChanged(const Camera& camera, const TrimSettings& settings) const;
    void applyShownColors();

    TrimRenderer& m_renderer;
    GlFunctions& m_gl;
    std::vector<std::unique_ptr<GpuScene>> m_levels;
    std::vector<DynamicRule> m_rules;
    std::vector<std::uint32_t> m_shownColors; ///< per mesh vertex; empty: the trim palette
    std::size_t m_meshVertices = 0;
    StaticRule m_baseRule = StaticRule::AlternatingBorder;
    GlBuffer m_state;
    GlBuffer m_bits[2];
    int m_stateWidth = 0;
    int m_stateHeight = 0;
    std::size_t m_bytes = 0;
    int m_shownReference = 0; ///< index into m_bits holding the last characterization
    /// Levels 0 .. m_characterized−1 are characterized for the cached view, the last of
    /// them into m_bits[m_shownReference]; 0: nothing cached.
    std::size_t m_characterized = 0;
    Camera m_cachedCamera;
    StaticRule m_cachedBaseRule = StaticRule::AlternatingBorder;
    int m_cachedMethod = -1;
    int m_cachedK = 0;
    DynamicFrameStats m_stats;
};

} // namespace trimlab::render
