#pragma once
/// \file
/// The designer workflow's model (thesis 8.1.1–8.2): the deformation history
/// (timeline::Timeline) of one trimmable mesh — object 0 of the shown scene, in object
/// space, with its model matrix —, the brush's connectivity and the frame shown. Its
/// edits go on the undo stack of the document it belongs to (ui/common/document.h, which
/// also keeps the project file and the modified state). No widget: the window, the brush and the timeline dock read it and change it
/// only through undo commands (append_frame_command.h, start_set_command.h,
/// set_rule_command.h), which call the edit functions below.
///
/// The brush edits the last frame only; earlier frames are shown (scrubbing, playback)
/// but never changed.
///
/// A history of an editable surface (Timeline::hasSurface(): NURBS or subdivision,
/// thesis 8.2) also has an EditableSurface, the evaluator of its fixed-connectivity mesh,
/// kept at the shown frame's control points (so the control net drawn is the shown
/// frame's). The timeline stays the truth: the surface only mirrors it, and a tool that
/// moves its points for a preview puts them back with syncSurface().

#include "core/deform/brush_topology.h"
#include "core/surface/editable_surface.h"
#include "core/timeline/timeline.h"

#include <glm/mat4x4.hpp>

#include <QObject>
#include <QString>

#include <memory>
#include <vector>

class QUndoStack;

namespace trimlab::ui {

class DesignSession : public QObject {
    Q_OBJECT
public:
    /// Continues `history` (its base mesh must be closed and oriented: trimmable), shown
    /// through `modelMatrix`, at its last frame; its undo commands go on `undoStack` (the
    /// document's), which must outlive the commands the session pushes.
    DesignSession(timeline::Timeline history, const glm::dmat4& modelMatrix, QUndoStack& undoStack,
                  QObject* parent = nullptr);
    ~DesignSession() override;

    [[nodiscard]] const timeline::Timeline& timeline() const { return m_timeline; }
    [[nodiscard]] const deform::BrushTopology& topology() const { return *m_topology; }
    /// The editable surface of a surface history (nullptr for a plain mesh history), at
    /// the shown frame's control points unless a tool is previewing a move.
    [[nodiscard]] EditableSurface* surface() const { return m_surface.get(); }
    /// Puts the surface back at the shown frame's control points (after a preview).
    void syncSurface();
    [[nodiscard]] const glm::dmat4& modelMatrix() const { return m_model; }
    /// Object-space bounds of the base mesh (the brush radius scales with them).
    [[nodiscard]] const Bounds& baseBounds() const { return m_baseBounds; }
    /// The document's undo stack the session's edits are pushed on.
    [[nodiscard]] QUndoStack* undoStack() const { return m_undo; }
    /// Increases with every change of frames or sets (caches key on it).
    [[nodiscard]] quint64 revision() const { return m_revision; }

    [[nodiscard]] int lastFrame() const { return m_timeline.frameCount() - 1; }
    [[nodiscard]] int shownFrame() const { return m_shownFrame; }
    [[nodiscard]] bool showsLastFrame() const { return m_shownFrame == lastFrame(); }
    /// The set new strokes go to: the last one.
    [[nodiscard]] int currentSet() const { return int(m_timeline.sets().size()) - 1; }
    /// Positions of the shown frame (#V, object space), exact.
    [[nodiscard]] const std::vector<glm::vec3>& shownPositions() const;
    /// Shows frame `frame` (clamped to 0 … lastFrame()); emits shownFrameChanged() if it
    /// changed.
    void showFrame(int frame);

    // Edits, for the undo commands. Each shows the last frame afterwards and emits
    // historyChanged(); they throw what Timeline throws.
    void appendFrame(timeline::Frame frame);
    timeline::Frame removeLastFrame();
    void startSet(DynamicRule rule);
    void removeLastSetIfEmpty();
    void setRule(int set, DynamicRule rule);

signals:
    /// Frames or sets changed (a stroke, undo, redo, a new set, a rule); the last frame
    /// is shown now.
    void historyChanged();
    /// Another frame is shown (showFrame(); edits emit historyChanged() only).
    void shownFrameChanged(int frame);

private:
    void afterEdit();

    timeline::Timeline m_timeline;
    std::unique_ptr<deform::BrushTopology> m_topology;
    std::unique_ptr<EditableSurface> m_surface;
    glm::dmat4 m_model;
    Bounds m_baseBounds;
    QUndoStack* m_undo;
    int m_shownFrame = 0;
    std::vector<glm::vec3> m_scrubbed; ///< positions of an earlier shown frame
    quint64 m_revision = 0;
};

} // namespace trimlab::ui
