// The interior-inspection parts of the main window (main_window.h): the Scene dock and
// its InspectScene, File ▸ Add Object…, how transform and CSG edits reach the viewport,
// and which undo stack the Edit menu acts on. Kept apart from main_window.cpp so that
// each file stays about one thing.
#include "main_window.h"

#include "design_session.h"
#include "design_workspace.h"
#include "inspect_scene.h"
#include "mesh_file_filter.h"
#include "project_files.h"
#include "render_panel.h"
#include "render_settings_store.h"
#include "scene_loader.h"
#include "scene_panel.h"
#include "viewport_widget.h"

#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QUndoGroup>
#include <QUndoStack>

#include <stdexcept>

namespace trimlab::ui {

namespace {

constexpr int kStatusMessageMs = 5000;

/// Makes `stack` the group's active stack unless it has left the group: a stack being
/// destroyed leaves its group first and then clears itself, which reports an index change.
void activateIfGrouped(QUndoGroup* group, QUndoStack* stack)
{
    if (group->stacks().contains(stack))
        group->setActiveStack(stack);
}

} // namespace

void MainWindow::createInspectDock()
{
    m_inspect = new InspectScene(this);
    m_scenePanel = new ScenePanel(*m_inspect);
    auto* scroll = new QScrollArea;
    scroll->setWidget(m_scenePanel);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    m_sceneDock = new QDockWidget(tr("Scene"), this);
    m_sceneDock->setObjectName(QStringLiteral("sceneDock"));
    m_sceneDock->setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea);
    m_sceneDock->setWidget(scroll);
    addDockWidget(Qt::RightDockWidgetArea, m_sceneDock);
    tabifyDockWidget(m_dock, m_sceneDock);
    m_dock->raise();
    m_objectLoader = new SceneLoader(this);
}

void MainWindow::connectInspectParts()
{
    connect(m_inspect, &InspectScene::csgChanged, this, &MainWindow::applyRenderChoices);
    connect(m_inspect, &InspectScene::transformChanged, this, &MainWindow::onObjectTransformChanged);
    connect(m_scenePanel, &ScenePanel::addObjectRequested, this, &MainWindow::showAddObjectDialog);
    connect(m_viewport, &ViewportWidget::objectDragged, this, [this](int object, const glm::dvec3& delta) {
        std::optional<ObjectTransform> transform = m_inspect->transform(object);
        if (!transform || !m_viewport->objectDragEnabled())
            return;
        transform->translation += delta;
        m_inspect->editTransform(object, *transform, true);
        m_scenePanel->setCurrentObject(object);
    });
    connect(m_viewport, &ViewportWidget::objectDragFinished, m_inspect, &InspectScene::endDrag);
    connect(m_objectLoader, &SceneLoader::loaded, this, &MainWindow::onObjectsLoaded);
    connect(m_objectLoader, &SceneLoader::failed, this, [this](const QString& source, const QString& message) {
        statusBar()->clearMessage();
        showMessage(QMessageBox::Critical, tr("Could not add"),
                    tr("Could not add “%1” to the scene.").arg(QFileInfo(source).fileName()), message);
        emit sceneLoadFailed(source, message);
    });
    QUndoGroup* group = m_design->undoGroup();
    QUndoStack* sceneStack = m_inspect->undoStack();
    group->addStack(sceneStack);
    connect(sceneStack, &QUndoStack::indexChanged, group, [group, sceneStack] { activateIfGrouped(group, sceneStack); });
    followUndoStacks();
    connect(m_design, &DesignWorkspace::sessionChanged, this, [this] {
        followUndoStacks();
        updateSceneEditability();
    });
}

// The stack edited last is the one Edit ▸ Undo acts on: the scene's, or the design
// session's while one is shown (it becomes active again with its next stroke).
void MainWindow::followUndoStacks()
{
    QUndoGroup* group = m_design->undoGroup();
    const DesignSession* session = m_design->session();
    if (!session) {
        group->setActiveStack(m_inspect->undoStack());
        return;
    }
    QUndoStack* designStack = session->undoStack();
    connect(designStack, &QUndoStack::indexChanged, group,
            [group, designStack] { activateIfGrouped(group, designStack); });
    group->setActiveStack(designStack);
}

void MainWindow::updateSceneEditability()
{
    QString reason;
    if (m_animation)
        reason = tr("The transforms of an animation's rest pose are fixed.");
    else if (m_design->session())
        reason = tr("The object is being designed (its deformation history works in its own frame); add another "
                    "object with File ▸ Add Object… to move objects.");
    m_scenePanel->setTransformsEditable(reason.isEmpty(), reason);
    m_viewport->setObjectDragEnabled(reason.isEmpty());
}

void MainWindow::showAddObjectDialog()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Add Object"), loadLastDirectory(*m_settings),
                                                      meshFileDialogFilter());
    if (path.isEmpty())
        return;
    saveLastDirectory(*m_settings, QFileInfo(path).absolutePath());
    addObject(path);
}

void MainWindow::addObject(const QString& source)
{
    QString problem;
    if (!m_scene)
        problem = tr("Open a scene first; Add Object loads a mesh into the scene shown.");
    else if (m_animation)
        problem = tr("Objects cannot be added to an animation.");
    if (!problem.isEmpty()) {
        showMessage(QMessageBox::Information, tr("Add Object"), tr("Nothing was added."), problem);
        return;
    }
    if (!m_projectFiles->maybeSave())
        return;
    statusBar()->showMessage(tr("Adding %1…").arg(QFileInfo(source).fileName()));
    m_objectLoader->load(source);
}

void MainWindow::onObjectsLoaded(std::shared_ptr<const LoadedScene> loaded)
{
    QString error;
    if (!m_inspect->appendObjects(*loaded, &error)) {
        showMessage(QMessageBox::Warning, tr("Add Object"), tr("Nothing was added."), error);
        return;
    }
    m_design->endSession(); // before the viewport takes the grown scene; a scene of several objects is not designed
    m_scene = m_inspect->scene();
    const Bounds bounds = m_scene->scene.worldBounds();
    m_panel->setSceneInfo(bounds, m_scene->trimmable(), QString::fromStdString(m_scene->trimUnavailableReason()));
    m_viewport->replaceScene(std::shared_ptr<const Scene>(m_scene, &m_scene->scene));
    applyRenderChoices();
    updateSceneEditability();
    m_scenePanel->setCurrentObject(m_inspect->objectCount() - 1);
    const QString source = QString::fromStdString(loaded->source);
    statusBar()->showMessage(tr("Added %1: the scene has %2 objects%3")
                                 .arg(QString::fromStdString(loaded->displayName))
                                 .arg(m_inspect->objectCount())
                                 .arg(m_inspect->objectCount() > kMaxCsgOperands
                                          ? tr(" (CSG and collisions address objects 0 to %1)").arg(kMaxCsgOperands - 1)
                                          : QString()),
                             kStatusMessageMs);
    emit objectAdded(source);
}

// A transform edit (or its undo) replaced the scene by one whose single model matrix
// differs: only the matrices go to the GPU, the camera stays.
void MainWindow::onObjectTransformChanged()
{
    m_scene = m_inspect->scene();
    std::shared_ptr<const Scene> scene(m_scene, &m_scene->scene);
    try {
        m_viewport->setSceneTransforms(scene);
    } catch (const std::invalid_argument&) {
        m_viewport->replaceScene(scene); // the view showed other geometry (never expected): upload it all
    }
    m_panel->setClipBounds(m_scene->scene.worldBounds());
}

} // namespace trimlab::ui
