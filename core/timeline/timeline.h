#pragma once
/// \file
/// The deformation history of the designer workflow (thesis 8.1.1–8.1.2, 8.2): a base
/// mesh and a sequence of frames, each frame one committed stroke. Frames are grouped
/// into *sets of concurrent disjoint deformations*; every set has one dynamic rule and
/// one reference frame, the frame just before its first stroke (so set 0's reference is
/// frame 0, the base mesh). Frame f >= 1 is the mesh after strokes 1..f.
///
/// Frames store the exact positions they changed (sparse), so positionsAt(f) is bit-exact
/// whatever the brush code does later, and undo restores positions bit for bit.
///
/// Editable surfaces (NURBS, subdivision; core/surface/): a timeline may also hold the
/// SurfaceDefinition its base mesh was tessellated from. Its frames are then either brush
/// strokes on the mesh or control-point edits (Frame::controlMoves), which store the
/// exact control points they moved as well as the exact mesh vertices that changed, so
/// the dynamic rules see them exactly like strokes (the tessellation's connectivity is
/// fixed) and controlPointsAt(f) is bit-exact like positionsAt(f).

#include "core/deform/stroke.h"
#include "core/mesh/triangle_mesh.h"
#include "core/surface/surface_definition.h"
#include "core/trim/dynamic_rule.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace trimlab::timeline {

/// One control point of an editable surface moved by a control-point edit: its index
/// into SurfaceDefinition::controlPoints() (< #C) and its exact positions (object space,
/// double precision) before and after the edit.
struct ControlPointMove {
    std::uint32_t index = 0;
    glm::dvec3 before{0.0};
    glm::dvec3 after{0.0};

    friend bool operator==(const ControlPointMove&, const ControlPointMove&) = default;
};

/// One committed edit and exactly what it changed: a brush stroke on the mesh, or a
/// control-point edit of the timeline's surface.
/// - Stroke frame: `controlMoves` is empty; `stroke` is the stroke.
/// - Control-point edit: `controlMoves` is not empty (isControlEdit()); `stroke` is
///   ignored (leave it default-constructed; it is neither validated beyond what a
///   default stroke passes nor saved).
/// In both, `vertices`/`before`/`after` are the mesh vertices whose bits changed.
struct Frame {
    deform::Stroke stroke;               ///< resolved (anchorTriangle set); unused by control edits
    std::vector<std::uint32_t> vertices; ///< moved vertices, sorted ascending, unique
    std::vector<glm::vec3> before;       ///< their positions in the previous frame
    std::vector<glm::vec3> after;        ///< their positions in this frame
    /// Control-point edits only: the moved control points, sorted ascending by index,
    /// unique, `before` equal (bits) to the previous frame's control points, `after`
    /// finite. Tied NURBS points (tiedControlPoints) are listed each, with equal values.
    std::vector<ControlPointMove> controlMoves;

    /// True for a control-point edit, false for a brush stroke.
    [[nodiscard]] bool isControlEdit() const { return !controlMoves.empty(); }

    /// Field-wise equality (floats by value; compare bit patterns where -0.0f matters).
    friend bool operator==(const Frame&, const Frame&) = default;
};

/// A set of concurrent disjoint deformations: frames [firstFrame, firstFrame + frameCount)
/// (1-based frame numbers) share reference frame firstFrame − 1.
struct DeformationSet {
    DynamicRule rule = DynamicRule::Confluent;
    int firstFrame = 1;
    int frameCount = 0;
    [[nodiscard]] int referenceFrame() const { return firstFrame - 1; }

    friend bool operator==(const DeformationSet&, const DeformationSet&) = default;
};

class Timeline {
public:
    Timeline() = default;
    /// Starts a history on `base` with one empty set of `firstRule`.
    explicit Timeline(TriangleMesh base, DynamicRule firstRule = DynamicRule::Confluent);
    /// Starts the history of an editable surface: `base` must be the tessellation of
    /// `surface` at its own control points (EditableSurface(surface).mesh(); use
    /// surfaceTimeline() in core/timeline/control_edit.h, which guarantees it — this
    /// constructor does not tessellate). Throws std::invalid_argument "Timeline: ..." for
    /// an invalid definition (requireValidSurfaceDefinition).
    Timeline(TriangleMesh base, SurfaceDefinition surface, DynamicRule firstRule = DynamicRule::Confluent);

    /// Rebuilds a history from its parts (what a project file stores). `sets` must be
    /// contiguous: sets[0].firstFrame == 1, each next set starts where the previous one
    /// ends, the counts add up to frames.size(), no count is negative, and there is at
    /// least one set (none only when there are no frames either: a default-constructed
    /// Timeline). Every frame must satisfy appendFrame's rules and every triangle
    /// index must be < #V. Throws std::invalid_argument naming the first problem
    /// ("frames[3]: vertex 9 is out of range (the mesh has 8 vertices)",
    /// "sets[1]: starts at frame 4, expected 3").
    /// `surface`: the editable surface's definition, or nullopt for a plain mesh history
    /// (then no frame may be a control edit: "frames[2]: a control-point edit needs a
    /// surface definition"). Control moves are checked like appendFrame's.
    [[nodiscard]] static Timeline restore(TriangleMesh base, std::vector<Frame> frames,
                                          std::vector<DeformationSet> sets,
                                          std::optional<SurfaceDefinition> surface = std::nullopt);

    [[nodiscard]] const TriangleMesh& base() const { return m_base; }
    /// The editable surface's definition (nullopt for a plain mesh history).
    [[nodiscard]] const std::optional<SurfaceDefinition>& surface() const { return m_surface; }
    [[nodiscard]] bool hasSurface() const { return m_surface.has_value(); }
    /// Number of frames including frame 0 (the base): strokes + 1.
    [[nodiscard]] int frameCount() const { return int(m_frames.size()) + 1; }
    [[nodiscard]] const Frame& frame(int f) const; ///< 1 <= f < frameCount(); else std::out_of_range
    [[nodiscard]] const std::vector<DeformationSet>& sets() const { return m_sets; }
    /// The set frame f belongs to (frame 0 and a set's reference belong to the set before,
    /// except frame 0 which belongs to set 0).
    [[nodiscard]] int setOfFrame(int f) const;

    /// Positions of frame f, reconstructed exactly (0 <= f < frameCount(); else
    /// std::out_of_range, as for setOfFrame, meshAt and chainTo).
    [[nodiscard]] std::vector<glm::vec3> positionsAt(int f) const;
    /// The mesh of frame f (base triangles, positionsAt(f)).
    [[nodiscard]] TriangleMesh meshAt(int f) const;
    /// Positions of the last frame (frameCount() − 1), kept up to date: no reconstruction.
    [[nodiscard]] const std::vector<glm::vec3>& currentPositions() const { return m_current; }
    /// Control points of frame f (#C, exact: the definition's points with every control
    /// move up to f applied); empty without a surface. std::out_of_range like positionsAt.
    [[nodiscard]] std::vector<glm::dvec3> controlPointsAt(int f) const;
    /// Control points of the last frame, kept up to date; empty without a surface.
    [[nodiscard]] const std::vector<glm::dvec3>& currentControlPoints() const { return m_currentControl; }

    /// Appends a frame to the last set. `frame.before` must equal the current last frame's
    /// positions of `frame.vertices` (std::invalid_argument otherwise).
    /// Also std::invalid_argument, naming the problem, when `frame.vertices` is not sorted
    /// ascending and unique or has an index >= #V, when the three arrays differ in size,
    /// when an 'after' position is not finite, or when the stroke is not storable
    /// (non-finite values, radius <= 0, smoothing step outside (0, 1], smoothing
    /// iterations outside [0, 10000]). "Equal" means equal bits (-0.0f != 0.0f). A frame
    /// may list no vertices (a stroke that moved nothing is still a frame). On a throw the
    /// timeline is unchanged.
    /// A control edit (frame.isControlEdit()) is also refused ("control move 2: ...")
    /// without a surface, when its indices are not sorted ascending and unique or are
    /// >= #C, when a 'before' differs (bits) from the current control point, when an
    /// 'after' is not finite, or when tied NURBS points (tiedControlPoints) would end
    /// with different positions.
    /// A history with a surface takes control edits only: a stroke frame is refused
    /// ("this history edits a NURBS surface through its control points; ..."), since the
    /// mesh must stay the surface evaluated at its control points (use the control-point
    /// brush, core/design/control_brush.h).
    void appendFrame(Frame frame);
    /// Removes the last frame (undo of a stroke or control edit) and returns it. The set it belonged to is
    /// kept even if it becomes empty; empty sets after it then start at the new last
    /// frame. std::logic_error when there is no stroke to remove.
    Frame removeLastFrame();
    /// Starts a new set whose reference is the current last frame. If the last set is still
    /// empty, only its rule changes (a set without strokes has nothing to remember).
    void startSet(DynamicRule rule);
    /// Undo of startSet: removes the last set if it is empty and not the only one.
    void removeLastSetIfEmpty();
    /// Changes the rule of set s (std::out_of_range when there is no set s).
    void setRule(int s, DynamicRule rule);

    /// What the dynamic renderer needs to show frame f: the chain of reference frames of
    /// every set up to f's, oldest first, with the rule of the set that starts from each.
    struct ChainLink {
        int referenceFrame;
        DynamicRule rule;
    };
    [[nodiscard]] std::vector<ChainLink> chainTo(int f) const;

    friend bool operator==(const Timeline&, const Timeline&) = default;

private:
    TriangleMesh m_base;
    std::vector<Frame> m_frames;
    std::vector<DeformationSet> m_sets;
    /// Positions of the last frame; derived from m_base and m_frames (so equal histories
    /// have equal caches and the defaulted operator== stays correct).
    std::vector<glm::vec3> m_current;
    std::optional<SurfaceDefinition> m_surface;
    /// Control points of the last frame (empty without a surface); derived like m_current.
    std::vector<glm::dvec3> m_currentControl;

    void checkFrame(const Frame& frame) const;
    void checkControlMoves(const Frame& frame) const;
};

} // namespace trimlab::timeline
