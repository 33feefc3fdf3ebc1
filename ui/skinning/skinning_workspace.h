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

signals:
    /// The user asked to export (the owner knows the playback rate).
    void exportRequested();

private:
    const WindowContext& m_context;
    SkinningPanel* m_panel = nullptr;
    QDockWidget* m_dock = nullptr;
};

} // namespace trimlab::ui
