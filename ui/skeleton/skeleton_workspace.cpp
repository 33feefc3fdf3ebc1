#include "ui/skeleton/skeleton_workspace.h"

#include "ui/common/window_context.h"
#include "ui/skeleton/skeleton_panel.h"
#include "ui/skeleton/skeleton_settings_store.h"

#include <QAction>
#include <QDockWidget>

namespace trimlab::ui {

SkeletonWorkspace::SkeletonWorkspace(const WindowContext& context, ViewportWidget* viewport, QDockWidget* tabWith,
                                     QAction* brushAction, QObject* parent)
    : QObject(parent), m_context(context), m_panel(new SkeletonPanel)
{
    m_panel->setViewport(viewport);
    m_dock = m_context.addSideDock(tr("Skeleton"), QStringLiteral("skeletonDock"), m_panel, tabWith);
    connect(m_panel, &SkeletonPanel::choicesChanged, this,
            [this] { saveSkeletonChoices(m_context.settings(), m_panel->choices()); });
    connect(m_panel, &SkeletonPanel::exportGltfRequested, this, &SkeletonWorkspace::exportRiggedGltf);
    connect(m_panel, &SkeletonPanel::exportJsonRequested, this, &SkeletonWorkspace::exportSkeletonJson);
    // One mouse tool at a time: the pose tool switches the brush off and the brush the pose tool.
    connect(m_panel, &SkeletonPanel::poseToolToggled, this, [brushAction](bool on) {
        if (on)
            brushAction->setChecked(false);
    });
    connect(brushAction, &QAction::toggled, this, [this](bool on) {
        if (on)
            m_panel->poseToolTakenOver();
    });
}

void SkeletonWorkspace::restoreSettings()
{
    m_panel->setChoices(loadSkeletonChoices(m_context.settings()));
}

void SkeletonWorkspace::exportRiggedGltf()
{
    const QString path =
        m_context.askSavePath(tr("Export Rigged glTF"), {tr("Binary glTF (*.glb)"), tr("glTF (*.gltf)")},
                              m_context.sceneBaseName(QStringLiteral("mesh")) + QStringLiteral("-rigged.glb"));
    if (path.isEmpty())
        return;
    QString error;
    if (m_panel->exportRiggedGltf(path, &error))
        m_context.showStatus(tr("Saved %1").arg(path));
    else
        m_context.showMessage(QMessageBox::Warning, tr("Export Rigged glTF"), tr("%1 was not saved.").arg(path), error);
}

void SkeletonWorkspace::exportSkeletonJson()
{
    const QString path =
        m_context.askSavePath(tr("Export Skeleton JSON"), {tr("Skeleton JSON (*.json)")},
                              m_context.sceneBaseName(QStringLiteral("mesh")) + QStringLiteral("-skeleton.json"));
    if (path.isEmpty())
        return;
    QString error;
    if (m_panel->exportSkeletonJson(path, &error))
        m_context.showStatus(tr("Saved %1").arg(path));
    else
        m_context.showMessage(QMessageBox::Warning, tr("Export Skeleton JSON"), tr("%1 was not saved.").arg(path),
                              error);
}

} // namespace trimlab::ui
