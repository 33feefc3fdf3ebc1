// The Skeleton dock of the main window (main_window.h, skeleton_panel.h): skeleton
// extraction, stage views, posing and export on the mesh shown. Kept apart from
// main_window.cpp so that each file stays about one thing.
#include "main_window.h"

#include "render_settings_store.h"
#include "skeleton_panel.h"
#include "skeleton_settings_store.h"

#include <QAction>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>

namespace trimlab::ui {

namespace {

constexpr int kStatusMessageMs = 5000;

} // namespace

void MainWindow::createSkeletonDock()
{
    m_skeleton = new SkeletonPanel;
    m_skeleton->setViewport(m_viewport);
    auto* scroll = new QScrollArea;
    scroll->setWidget(m_skeleton);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    m_skeletonDock = new QDockWidget(tr("Skeleton"), this);
    m_skeletonDock->setObjectName(QStringLiteral("skeletonDock"));
    m_skeletonDock->setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea);
    m_skeletonDock->setWidget(scroll);
    addDockWidget(Qt::RightDockWidgetArea, m_skeletonDock);
    tabifyDockWidget(m_dock, m_skeletonDock);
    m_dock->raise();
}

void MainWindow::connectSkeletonParts()
{
    connect(m_skeleton, &SkeletonPanel::choicesChanged, this,
            [this] { saveSkeletonChoices(*m_settings, m_skeleton->choices()); });
    connect(m_skeleton, &SkeletonPanel::exportGltfRequested, this, &MainWindow::showExportRiggedGltfDialog);
    connect(m_skeleton, &SkeletonPanel::exportJsonRequested, this, &MainWindow::showExportSkeletonJsonDialog);
    // One mouse tool at a time: the pose tool switches the brush off and the brush the pose tool.
    connect(m_skeleton, &SkeletonPanel::poseToolToggled, this, [this](bool on) {
        if (on)
            m_brushAction->setChecked(false);
    });
    connect(m_brushAction, &QAction::toggled, this, [this](bool on) {
        if (on)
            m_skeleton->poseToolTakenOver();
    });
}

// Asks for a file (in the last directory), adds the filter's suffix when the name has
// none of `suffixes`, remembers the directory. "" when the user cancels.
QString MainWindow::askSkeletonExportPath(const QString& title, const QStringList& filters, const QString& ending)
{
    const QString name = m_scene ? QFileInfo(QString::fromStdString(m_scene->displayName)).completeBaseName()
                                 : QStringLiteral("mesh");
    const QString suggested = loadLastDirectory(*m_settings) + QLatin1Char('/') + name + ending;
    QString filter = filters.front();
    QString path = QFileDialog::getSaveFileName(this, title, suggested, filters.join(QStringLiteral(";;")), &filter);
    if (path.isEmpty())
        return {};
    const QRegularExpression suffixes(QStringLiteral("\\*(\\.\\w+)"));
    bool known = false;
    for (const QString& f : filters)
        known = known || path.endsWith(suffixes.match(f).captured(1), Qt::CaseInsensitive);
    if (!known)
        path += suffixes.match(filter).captured(1);
    saveLastDirectory(*m_settings, QFileInfo(path).absolutePath());
    return path;
}

void MainWindow::showExportRiggedGltfDialog()
{
    const QString path = askSkeletonExportPath(tr("Export Rigged glTF"), {tr("Binary glTF (*.glb)"), tr("glTF (*.gltf)")},
                                               QStringLiteral("-rigged.glb"));
    if (path.isEmpty())
        return;
    QString error;
    if (m_skeleton->exportRiggedGltf(path, &error))
        statusBar()->showMessage(tr("Saved %1").arg(path), kStatusMessageMs);
    else
        showMessage(QMessageBox::Warning, tr("Export Rigged glTF"), tr("%1 was not saved.").arg(path), error);
}

void MainWindow::showExportSkeletonJsonDialog()
{
    const QString path = askSkeletonExportPath(tr("Export Skeleton JSON"), {tr("Skeleton JSON (*.json)")},
                                               QStringLiteral("-skeleton.json"));
    if (path.isEmpty())
        return;
    QString error;
    if (m_skeleton->exportSkeletonJson(path, &error))
        statusBar()->showMessage(tr("Saved %1").arg(path), kStatusMessageMs);
    else
        showMessage(QMessageBox::Warning, tr("Export Skeleton JSON"), tr("%1 was not saved.").arg(path), error);
}

} // namespace trimlab::ui
