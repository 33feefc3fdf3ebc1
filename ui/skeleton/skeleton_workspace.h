#pragma once
/// \file
/// The skeleton feature of the main window (skeleton extraction by mesh contraction,
/// Berenguer & Moreno): the Skeleton dock (SkeletonPanel: the stages in the background,
/// each shown in the viewport, posing the rig live under the trim renderer), its choices
/// persisted in the settings, and the exports of the rigged glTF and the skeleton JSON.
/// Its pose tool and the design brush share the viewport's mouse: turning one on turns
/// the other off.

#include <QObject>

class QAction;
class QDockWidget;

namespace trimlab::ui {

class SkeletonPanel;
class ViewportWidget;
class WindowContext;

class SkeletonWorkspace : public QObject {
    Q_OBJECT
public:
    /// The dock is tabbed with `tabWith`; `brushAction` is the design brush's toggle.
    SkeletonWorkspace(const WindowContext& context, ViewportWidget* viewport, QDockWidget* tabWith,
                      QAction* brushAction, QObject* parent = nullptr);

    [[nodiscard]] SkeletonPanel* panel() const { return m_panel; }
    [[nodiscard]] QDockWidget* dock() const { return m_dock; }
    /// The saved choices into the panel.
    void restoreSettings();

private:
    void exportRiggedGltf();
    void exportSkeletonJson();

    const WindowContext& m_context;
    SkeletonPanel* m_panel = nullptr;
    QDockWidget* m_dock = nullptr;
};

} // namespace trimlab::ui
