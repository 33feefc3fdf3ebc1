#pragma once
/// \file
/// The skinning feature of the main window (thesis chapter 4): the Skinning dock, shown
/// while an animation is open (SkinningPanel: fit in the background, E_RMS chart, bone
/// edits), and its export — the dialog, and the E_RMS of the written file against the
/// original animation. What the panel shows (the approximation's poses, the error heat
/// map) takes the place of the original poses and the segment colours; the animation
/// feature (animation/animation_workspace.h) asks it per pose.

#include <QObject>

class QDockWidget;

namespace trimlab::ui {

class SkinningPanel;
class WindowContext;

class SkinningWorkspace : public QObject {
    Q_OBJECT
public:
    /// The dock is tabbed with `tabWith` and hidden until an animation is shown.
    SkinningWorkspace(const WindowContext& context, QDockWidget* tabWith, QObject* parent = nullptr);

    [[nodiscard]] SkinningPanel* panel() const { return m_panel; }
    [[nodiscard]] QDockWidget* dock() const { return m_dock; }
    /// The export dialog; the glTF plays at `fps`.
    void showExportDialog(double fps);
    /// Whether the fit's bone edits may be thrown away (another file is about to replace
    /// the animation, or the window closes): true when there are none that were not
    /// exported, or when the user chose Discard. Export… opens the export dialog (the
    /// glTF at `fps`) and answers false, as Cancel does.
    [[nodiscard]] bool confirmDiscardEdits(double fps);
    /// Bone edits made since the fit or the last export that wrote them.
    [[nodiscard]] bool hasUnexportedEdits() const;

signals:
    /// The user asked to export (the owner knows the playback rate).
    void exportRequested();

private:
    const WindowContext& m_context;
    SkinningPanel* m_panel = nullptr;
    QDockWidget* m_dock = nullptr;
    /// The undo index of the edits the running export writes (-1: none runs).
    int m_exportIndex = -1;
};

} // namespace trimlab::ui
