#pragma once
/// \file
/// The editable-surface feature of the main window (thesis 8.2): the Create menu (NURBS
/// primitives and files, subdivision surfaces from built-in cages or an OBJ cage file),
/// the Surface dock (density, degree, level, scheme and mode; the net; moves along the
/// normal), Edit ▸ Control Points (P) — exclusive with the brush — and Save NURBS
/// Surface As…. A created surface becomes a design session whose base mesh is its
/// tessellation (SceneHost::showHistory); changing parameters that change the mesh's
/// connectivity rebuilds it as a new history, after asking when edits would be lost.

#include "core/surface/subdivision_cage.h"
#include "core/surface/surface_definition.h"

#include <QObject>
#include <QString>

class QAction;
class QDockWidget;
class QMenuBar;

namespace trimlab::ui {

class DesignWorkspace;
class SurfacePanel;
class WindowContext;
enum class NurbsPrimitive;

class SurfaceWorkspace : public QObject {
    Q_OBJECT
public:
    /// The dock is tabbed with the design feature's Brush dock.
    SurfaceWorkspace(const WindowContext& context, DesignWorkspace& design, QObject* parent = nullptr);

    [[nodiscard]] SurfacePanel* panel() const { return m_panel; }
    [[nodiscard]] QDockWidget* dock() const { return m_dock; }
    /// Edit ▸ Control Points (P, checkable; exclusive with the brush).
    [[nodiscard]] QAction* controlPointsAction() const { return m_controlPointsAction; }
    /// Adds the Create menu to `menuBar`.
    void addCreateMenu(QMenuBar* menuBar);

    /// Create ▸ Subdivision Surface ▸ From Cage File… without the dialog (MainWindow's
    /// createSurfaceFromCageFile). Errors are reported as failed opens; false then.
    bool createFromCageFile(const QString& path);
    /// Create ▸ NURBS ▸ From NURBS File… without the dialog: the file's first surface.
    bool createFromNurbsFile(const QString& path);
    /// Create ▸ NURBS ▸ Save NURBS Surface As… without the dialog.
    bool saveNurbsSurface(const QString& path);

private:
    void createControlPointsAction();
    void connectParts();
    void showSurfaceInPanel();
    void createNurbsPrimitive(NurbsPrimitive primitive);
    void createSubdivisionFromCage(SubdivisionCage cage, const QString& label);
    [[nodiscard]] QString askSurfaceFile(const QString& title, const QString& filter);
    void showCreateFromCageDialog();
    void showCreateFromNurbsDialog();
    void showSaveNurbsDialog();
    bool createSession(const SurfaceDefinition& definition, const QString& name, bool askToSave);
    void rebuildSurface();
    [[nodiscard]] QString sceneName(const QString& fallback) const;

    const WindowContext& m_context;
    DesignWorkspace& m_design;
    SurfacePanel* m_panel = nullptr;
    QDockWidget* m_dock = nullptr;
    QAction* m_controlPointsAction = nullptr;
    QAction* m_saveNurbsAction = nullptr;
};

} // namespace trimlab::ui
