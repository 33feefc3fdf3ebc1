#pragma once
/// \file
/// Wires the designer workflow together: the DesignSession of the shown mesh, the brush
/// tool on the viewport, the Brush panel, the Deformation timeline dock, and how the
/// viewport shows the session's shown frame — by the static rule (the frame's positions
/// as object 0's pose) or by the dynamic rules (the chain to the frame, rebuilt when the
/// history or the shown frame changes; a drag replaces only its shown level). Holds no
/// algorithm: the history is core/timeline's, the chain core/trim's, the rendering
/// render/'s.
///
/// A history of an editable surface (NURBS, subdivision) also gets its control net drawn
/// over the view (ControlNetOverlay, at the shown frame's control points) and the
/// control-point tool (ControlPointTool); "Move along normal" edits the selection.
///
/// One undo group for the window: each session's stack becomes its active stack, so the
/// Edit menu's Undo/Redo follow the session shown.

#include "deform/stroke.h"
#include "mesh/triangle_mesh.h"
#include "timeline/timeline.h"
#include "trim/static_rule.h"

#include <glm/mat4x4.hpp>

#include <QObject>
#include <QString>

#include <memory>
#include <optional>

class QUndoGroup;

namespace trimlab::ui {

class BrushDrag;
class BrushTool;
class ControlNetOverlay;
class ControlPointTool;
class DeformationTimelinePanel;
class DesignSession;
class TrimmedRegionCheck;
class ViewportWidget;

class DesignWorkspace : public QObject {
    Q_OBJECT
public:
    DesignWorkspace(ViewportWidget* viewport, DeformationTimelinePanel* timelinePanel, QObject* parent = nullptr);
    ~DesignWorkspace() override;

    /// Replaces the session (the viewport must already show a scene whose object 0 is
    /// `history`'s base mesh through `model`). Clean undo stack; shows the last frame.
    void startSession(timeline::Timeline history, const glm::dmat4& model, const QString& projectPath);
    /// No session (an animation or an untrimmable scene is shown).
    void endSession();
    [[nodiscard]] DesignSession* session() const { return m_session.get(); }
    [[nodiscard]] QUndoGroup* undoGroup() const { return m_undoGroup; }
    [[nodiscard]] BrushTool* brushTool() const { return m_brush; }
    [[nodiscard]] ControlPointTool* controlPointTool() const { return m_points; }
    [[nodiscard]] ControlNetOverlay* controlNetOverlay() const { return m_overlay; }
    /// Moves the selected control points by `distance` (object units, > 0 outward) along
    /// their average normal as one undoable frame; a status message says why when
    /// nothing can move (no surface, no selection, an earlier frame shown, no normal).
    void moveSelectionAlongNormal(double distance);
    /// True when the session has changes its project file does not hold.
    [[nodiscard]] bool isModified() const;

    /// How the viewport classifies: dynamic rules (per set) or the static rule alone;
    /// `baseRule` classifies the base mesh; without trimming the static path is used.
    void setRenderMode(bool dynamicRules, StaticRule baseRule, bool trimEnabled);
    [[nodiscard]] bool showsDynamicRules() const { return m_session && m_dynamicRules && m_trimEnabled; }
    void setBrushSettings(const deform::BrushSettings& settings);

    /// "New set": an undoable StartSetCommand with `rule`.
    void startNewSet(DynamicRule rule);
    /// Gives the current set `rule` (an undoable SetRuleCommand; nothing if unchanged).
    void chooseRule(DynamicRule rule);
    void showFrame(int frame);

    /// Milliseconds the last homogeneous confluent check took (chain and rays), 0 before.
    [[nodiscard]] double lastTrimCheckMilliseconds() const { return m_lastCheckMs; }

signals:
    /// A session started or ended.
    void sessionChanged();
    void statusMessage(const QString& message);
    /// The session's undo stack became clean or modified.
    void modifiedChanged(bool modified);

private:
    void refreshView();
    void showControlNet();
    void onHistoryChanged();
    void extendViewBounds(const std::vector<glm::vec3>& positions);
    void refreshTimelinePanel();
    [[nodiscard]] std::optional<QString> trimmedRegionRefusal(const BrushDrag& drag);
    /// The homogeneous confluent rule for a control edit: refuses a frame that moves a
    /// trimmed-off part of the last frame.
    [[nodiscard]] std::optional<QString> controlEditRefusal(const timeline::Frame& frame);
    [[nodiscard]] std::optional<QString> trimmedSampleRefusal(const std::vector<std::uint32_t>& sample);

    ViewportWidget* m_viewport;
    DeformationTimelinePanel* m_timelinePanel;
    QUndoGroup* m_undoGroup;
    BrushTool* m_brush;
    ControlNetOverlay* m_overlay;
    ControlPointTool* m_points;
    std::unique_ptr<DesignSession> m_session;
    bool m_dynamicRules = false;
    bool m_trimEnabled = true;
    StaticRule m_baseRule = StaticRule::AlternatingBorder;
    std::unique_ptr<TrimmedRegionCheck> m_check; ///< for the last frame at m_checkRevision
    quint64 m_checkRevision = 0;
    StaticRule m_checkBaseRule = StaticRule::AlternatingBorder;
    double m_lastCheckMs = 0.0;
    /// World bounds of every frame so far: the camera's depth range must enclose them.
    Bounds m_viewBounds;
};

} // namespace trimlab::ui
