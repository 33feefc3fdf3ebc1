#pragma once
/// \file
/// The interior-inspection feature of the main window: the Scene dock (objects, their
/// transforms and rules, the CSG expression: ScenePanel over an InspectScene), File ▸ Add
/// Object… (a mesh loaded off the UI thread into the shown scene), Ctrl+drag of an object
/// in the view; its edits go on the undo stack of the document shown. (Clipping, capping
/// and highlighting are groups of the Render panel: render_panel/.)
///
/// Transforms cannot be edited while an animation is shown (its rest pose is fixed) or
/// while the single object is being designed (its history works in its own frame).

#include "core/catalog/scene_source.h"
#include "core/trim/inspect_settings.h"

#include <QObject>
#include <QString>

#include <functional>
#include <memory>

class QDockWidget;

namespace trimlab::ui {

class DesignSession;
class InspectScene;
class SceneLoader;
class ScenePanel;
class ViewportWidget;
class WindowContext;

class InspectWorkspace : public QObject {
    Q_OBJECT
public:
    /// The Scene dock is tabbed with `tabWith`.
    InspectWorkspace(const WindowContext& context, ViewportWidget* viewport, QDockWidget* tabWith,
                     QObject* parent = nullptr);

    [[nodiscard]] InspectScene* scene() const { return m_inspect; }
    [[nodiscard]] ScenePanel* panel() const { return m_panel; }
    [[nodiscard]] QDockWidget* dock() const { return m_dock; }
    [[nodiscard]] SceneLoader* objectLoader() const { return m_loader; }
    [[nodiscard]] const CsgSettings& csg() const;
    /// The scene shown is an animation's rest pose.
    [[nodiscard]] bool showsAnimation() const { return m_animation; }

    /// Another scene is shown (an animation's rest pose when `animation`): no CSG, its
    /// transforms, edits on the new document's undo stack.
    void showScene(std::shared_ptr<const LoadedScene> scene, bool animation);
    /// The design session started or ended (nullptr): whether transforms may be edited.
    void setDesignSession(const DesignSession* session);
    /// Asked before an object is added (the designed object stops being designed):
    /// false when the user keeps the unsaved design changes and nothing is added.
    void setSaveGuard(std::function<bool()> guard) { m_saveGuard = std::move(guard); }
    /// Loads the mesh file (or "demo:NAME") `source` off the UI thread and appends its
    /// objects to the shown scene (objectsAppended()), after the save guard; refused with
    /// a dialog without a scene or while an animation is shown.
    void addObject(const QString& source);
    /// File ▸ Add Object…: asks for the file, then addObject().
    void showAddObjectDialog();

signals:
    /// `source`'s objects were appended: the grown scene is scene()->scene().
    void objectsAppended(const QString& source, const QString& displayName);
    /// An object moved (or its move was undone): the scene is scene()->scene().
    void transformed();
    /// The CSG expression changed.
    void csgChanged();
    /// Adding `source` failed with `message` (after its dialog).
    void addFailed(const QString& source, const QString& message);

private:
    void connectParts();
    void updateEditability();
    void onObjectsLoaded(std::shared_ptr<const LoadedScene> loaded);
    void moveObject(int object, const glm::dvec3& delta);

    const WindowContext& m_context;
    ViewportWidget* m_viewport;
    InspectScene* m_inspect = nullptr;
    ScenePanel* m_panel = nullptr;
    QDockWidget* m_dock = nullptr;
    SceneLoader* m_loader = nullptr;
    const DesignSession* m_session = nullptr;
    bool m_animation = false;
    std::function<bool()> m_saveGuard;
};

} // namespace trimlab::ui
