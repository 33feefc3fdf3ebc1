#pragma once
/// \file
/// The designer feature of the main window (docs/designer-workflow.md): the DesignSession
/// of the shown mesh, the brush tool on the viewport, the Brush dock, the Deformation
/// timeline dock, the Edit actions (Undo, Redo, Brush B, New Set N), the project files
/// (ProjectFiles, with autosave and recovery: SessionRecovery) and the history exports
/// with their File menu entries — and what the view shows of the session, published as
/// the design history (render/content_publisher.h): the shown frame's positions as object
/// 0's pose, and under the dynamic rules the chain to the frame (rebuilt when the history,
/// the shown frame or the rules change; a drag replaces only its shown level). When
/// another feature's pose is shown on the designed mesh (a skeleton pose), the chain's
/// last level deforms the current set's reference into that pose, so the dynamic rules
/// classify what the view shows; this workspace is the one place that does so. Holds no
/// algorithm: the history is core/timeline's, the chain core/design's, the rendering
/// render/'s.
///
/// A history of an editable surface (NURBS, subdivision) also gets its control net drawn
/// over the view (ControlNetOverlay, at the shown frame's control points) and the
/// control-point tool (ControlPointTool); "Move along normal" edits the selection. The
/// surface feature (ui/surface/surface_workspace.h) owns their dock and action.
///
/// One undo group for the window: each session's stack becomes its active stack, so the
/// Edit menu's Undo/Redo follow the session shown. The brush choices and the timeline's
/// playback rate persist in the settings.

#include "render/content_publisher.h"

#include "core/deform/stroke.h"
#include "core/mesh/triangle_mesh.h"
#include "core/timeline/project_file.h"
#include "core/timeline/timeline.h"
#include "core/trim/dynamic_chain.h"
#include "core/trim/static_rule.h"

#include <glm/mat4x4.hpp>

#include <QObject>
#include <QString>

#include <memory>
#include <optional>
#include <vector>

class QAction;
class QDockWidget;
class QMenu;
class QUndoGroup;

namespace trimlab::ui {

class BrushPanel;
class BrushTool;
class ControlNetOverlay;
class ControlPointTool;
class DeformationTimelinePanel;
class CurrentDocument;
class DesignSession;
class Document;
class HistoryExports;
class ProjectFiles;
class SessionRecovery;
class TrimmedRegionGuard;
class ViewportWidget;
class WindowContext;

class DesignWorkspace : public QObject {
    Q_OBJECT
public:
    /// The Brush dock is tabbed with `tabWith`.
    DesignWorkspace(const WindowContext& context, ViewportWidget* viewport, QDockWidget* tabWith,
                    QObject* parent = nullptr);
    ~DesignWorkspace() override;

    /// Replaces the session (the viewport must already show a scene whose object 0 is
    /// `history`'s base mesh through `model`); its edits go on the current document's undo
    /// stack. Shows the last frame.
    void startSession(timeline::Timeline history, const glm::dmat4& model);
    /// No session (an animation or an untrimmable scene is shown). The session's commands
    /// leave the document's undo stack with it.
    void endSession();
    [[nodiscard]] DesignSession* session() const { return m_session.get(); }
    /// The document shown (nullptr before the first), whose undo stack the session uses.
    [[nodiscard]] Document* document() const;
    /// Its holder (replaced() when another is shown).
    [[nodiscard]] CurrentDocument& currentDocument() const;
    [[nodiscard]] QUndoGroup* undoGroup() const { return m_undoGroup; }
    [[nodiscard]] BrushTool* brushTool() const { return m_brush; }
    [[nodiscard]] ControlPointTool* controlPointTool() const { return m_points; }
    [[nodiscard]] ControlNetOverlay* controlNetOverlay() const { return m_overlay; }
    [[nodiscard]] ViewportWidget* viewport() const { return m_viewport; }
    [[nodiscard]] BrushPanel* brushPanel() const { return m_brushPanel; }
    [[nodiscard]] DeformationTimelinePanel* timelinePanel() const { return m_timelinePanel; }
    [[nodiscard]] QDockWidget* brushDock() const { return m_brushDock; }
    [[nodiscard]] QDockWidget* timelineDock() const { return m_timelineDock; }
    [[nodiscard]] ProjectFiles* projectFiles() const { return m_projectFiles; }
    [[nodiscard]] SessionRecovery* sessionRecovery() const { return m_recovery; }
    [[nodiscard]] HistoryExports* historyExports() const { return m_exports; }
    /// Edit ▸ Undo and Redo (of the undo group), Brush (B, checkable) and New Set (N).
    [[nodiscard]] QAction* undoAction() const { return m_undoAction; }
    [[nodiscard]] QAction* redoAction() const { return m_redoAction; }
    [[nodiscard]] QAction* brushAction() const { return m_brushAction; }
    [[nodiscard]] QAction* newSetAction() const { return m_newSetAction; }
    /// Adds Save Project, Save Project As…, Export ▸ and the stroke-script entries to the
    /// File menu (enabled while a session is shown).
    void addFileActions(QMenu* file);
    /// The saved brush choices and playback rate.
    void restoreSettings();

    /// What a project saves beside the history or scene: the camera (in the mesh's object
    /// space; the project has no model matrix), the static rule and the rest of the
    /// document's view settings, relative to the shown scene's bounds.
    [[nodiscard]] timeline::ProjectExtras projectExtras() const;
    /// Moves the selected control points by `distance` (object units, > 0 outward) along
    /// their average normal as one undoable frame; a status message says why when
    /// nothing can move (no surface, no selection, an earlier frame shown, no normal).
    void moveSelectionAlongNormal(double distance);
    /// True when the document shown has changes its project file does not hold.
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
    [[nodiscard]] double lastTrimCheckMilliseconds() const;

signals:
    /// A session started or ended.
    void sessionChanged();
    void statusMessage(const QString& message);

private:
    void createDocks(QDockWidget* tabWith);
    void createActions();
    void createFileParts();
    void connectParts();
    void onSessionChanged();
    void refreshView();
    void refreshChain();
    void onShownPoseChanged();
    [[nodiscard]] const std::vector<glm::vec3>* foreignPose() const;
    [[nodiscard]] DynamicChain shownChain() const;
    void showControlNet();
    void frameControlNet(const std::vector<glm::dvec3>& points);
    void onHistoryChanged();
    void extendViewBounds(const std::vector<glm::vec3>& positions);
    void refreshTimelinePanel();

    const WindowContext& m_context;
    ViewportWidget* m_viewport;
    DeformationTimelinePanel* m_timelinePanel = nullptr;
    QDockWidget* m_timelineDock = nullptr;
    BrushPanel* m_brushPanel = nullptr;
    QDockWidget* m_brushDock = nullptr;
    QUndoGroup* m_undoGroup;
    BrushTool* m_brush;
    ControlNetOverlay* m_overlay;
    ControlPointTool* m_points;
    QAction* m_undoAction = nullptr;
    QAction* m_redoAction = nullptr;
    QAction* m_brushAction = nullptr;
    QAction* m_newSetAction = nullptr;
    render::ContentPublisher m_shown; ///< the design history's pose and chain
    render::ContentSubscription m_poseWatch;
    bool m_showingFrame = false;       ///< refreshView is publishing the shown frame
    bool m_chainOfForeignPose = false; ///< the chain shown ends in another feature's pose
    ProjectFiles* m_projectFiles = nullptr;
    SessionRecovery* m_recovery = nullptr;
    HistoryExports* m_exports = nullptr;
    std::unique_ptr<DesignSession> m_session;
    std::unique_ptr<TrimmedRegionGuard> m_guard;
    bool m_dynamicRules = false;
    bool m_trimEnabled = true;
    StaticRule m_baseRule = StaticRule::AlternatingBorder;
    /// World bounds of every frame so far: the camera's depth range must enclose them.
    Bounds m_viewBounds;
};

} // namespace trimlab::ui
