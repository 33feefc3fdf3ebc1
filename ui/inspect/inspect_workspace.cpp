#include "ui/inspect/inspect_workspace.h"

#include "ui/common/current_document.h"
#include "ui/common/window_context.h"
#include "ui/design/design_session.h"
#include "ui/inspect/inspect_scene.h"
#include "ui/inspect/scene_panel.h"
#include "ui/viewport/viewport_widget.h"
#include "ui/common/mesh_file_filter.h"
#include "ui/common/scene_loader.h"

#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMainWindow>
#include <QStatusBar>
#include <QUndoStack>

#include <stdexcept>

namespace trimlab::ui {

InspectWorkspace::InspectWorkspace(const WindowContext& context, ViewportWidget* viewport, QDockWidget* tabWith,
                                   QObject* parent)
    : QObject(parent),
      m_context(context),
      m_viewport(viewport),
      m_inspect(new InspectScene(this)),
      m_loader(new SceneLoader(&context.window()))
{
    m_panel = new ScenePanel(*m_inspect);
    m_dock = m_context.addSideDock(tr("Scene"), QStringLiteral("sceneDock"), m_panel, tabWith);
    connectParts();
}

const CsgSettings& InspectWorkspace::csg() const
{
    return m_inspect->csg();
}

void InspectWorkspace::connectParts()
{
    connect(m_inspect, &InspectScene::csgChanged, this, &InspectWorkspace::csgChanged);
    connect(m_inspect, &InspectScene::transformChanged, this, &InspectWorkspace::transformed);
    connect(m_panel, &ScenePanel::addObjectRequested, this, &InspectWorkspace::showAddObjectDialog);
    connect(m_viewport, &ViewportWidget::objectDragged, this, &InspectWorkspace::moveObject);
    connect(m_viewport, &ViewportWidget::objectDragFinished, m_inspect, &InspectScene::endDrag);
    connect(m_loader, &SceneLoader::loaded, this, &InspectWorkspace::onObjectsLoaded);
    connect(m_loader, &SceneLoader::failed, this, [this](const QString& source, const QString& message) {
        m_context.window().statusBar()->clearMessage();
        m_context.showMessage(QMessageBox::Critical, tr("Could not add"),
                              tr("Could not add “%1” to the scene.").arg(QFileInfo(source).fileName()), message);
        emit addFailed(source, message);
    });
}

void InspectWorkspace::moveObject(int object, const glm::dvec3& delta)
{
    std::optional<ObjectTransform> transform = m_inspect->transform(object);
    if (!transform || !m_viewport->objectDragEnabled())
        return;
    transform->translation += delta;
    m_inspect->editTransform(object, *transform, true);
    m_panel->setCurrentObject(object);
}

void InspectWorkspace::showScene(std::shared_ptr<const LoadedScene> scene, bool animation)
{
    m_animation = animation;
    Document* document = m_context.document().get();
    // No CSG, the transforms of the new scene; edits on the document's undo stack.
    m_inspect->reset(std::move(scene), document ? document->undoStack() : nullptr);
    updateEditability();
}

void InspectWorkspace::setDesignSession(const DesignSession* session)
{
    m_session = session;
    updateEditability();
}

void InspectWorkspace::updateEditability()
{
    QString reason;
    if (m_animation)
        reason = tr("The transforms of an animation's rest pose are fixed.");
    else if (m_session)
        reason = tr("The object is being designed (its deformation history works in its own frame); add another "
                    "object with File ▸ Add Object… to move objects.");
    m_panel->setTransformsEditable(reason.isEmpty(), reason);
    m_viewport->setObjectDragEnabled(reason.isEmpty());
}

void InspectWorkspace::showAddObjectDialog()
{
    const QString path = QFileDialog::getOpenFileName(&m_context.window(), tr("Add Object"), m_context.lastDirectory(),
                                                      meshFileDialogFilter());
    if (path.isEmpty())
        return;
    m_context.rememberDirectory(QFileInfo(path).absolutePath());
    addObject(path);
}

void InspectWorkspace::addObject(const QString& source)
{
    QString problem;
    if (!m_inspect->scene())
        problem = tr("Open a scene first; Add Object loads a mesh into the scene shown.");
    else if (m_animation)
        problem = tr("Objects cannot be added to an animation.");
    if (!problem.isEmpty()) {
        m_context.showMessage(QMessageBox::Information, tr("Add Object"), tr("Nothing was added."), problem);
        return;
    }
    if (m_saveGuard && !m_saveGuard())
        return;
    m_context.showStatus(tr("Adding %1…").arg(QFileInfo(source).fileName()), 0);
    m_loader->load(source);
}

void InspectWorkspace::onObjectsLoaded(std::shared_ptr<const LoadedScene> loaded)
{
    QString error;
    if (!m_inspect->appendObjects(*loaded, &error)) {
        m_context.showMessage(QMessageBox::Warning, tr("Add Object"), tr("Nothing was added."), error);
        return;
    }
    m_panel->setCurrentObject(m_inspect->objectCount() - 1);
    emit objectsAppended(QString::fromStdString(loaded->source), QString::fromStdString(loaded->displayName));
}

} // namespace trimlab::ui
