#include "ui/skinning/skinning_workspace.h"

#include "ui/common/window_context.h"
#include "ui/skinning/skinning_panel.h"

#include <QDockWidget>

namespace trimlab::ui {

SkinningWorkspace::SkinningWorkspace(const WindowContext& context, QDockWidget* tabWith, QObject* parent)
    : QObject(parent), m_context(context), m_panel(new SkinningPanel)
{
    m_dock = m_context.addSideDock(tr("Skinning"), QStringLiteral("skinningDock"), m_panel, tabWith);
    m_dock->hide(); // shown while an animation is open
    connect(m_panel, &SkinningPanel::exportRequested, this, &SkinningWorkspace::exportRequested);
    connect(m_panel, &SkinningPanel::exportFinished, this, [this](const QString& path, double eRms, const QString& kind) {
        m_context.showMessage(QMessageBox::Information, tr("Export Skinning"), tr("Saved %1").arg(path),
                              tr("E_RMS of the exported file against the original animation: %1 (%2)")
                                  .arg(SkinningPanel::formatERms(eRms), kind));
    });
    connect(m_panel, &SkinningPanel::exportFailed, this, [this](const QString& path, const QString& message) {
        m_context.showMessage(QMessageBox::Warning, tr("Export Skinning"), tr("%1 was not saved.").arg(path), message);
    });
}

void SkinningWorkspace::showExportDialog(double fps)
{
    const QString path = m_context.askSavePath(tr("Export Skinning"), {tr("glTF (*.gltf)"), tr("Binary glTF (*.glb)")},
                                               m_context.sceneBaseName(QStringLiteral("animation")) +
                                                   QStringLiteral("-skinned.gltf"));
    if (!path.isEmpty())
        m_panel->exportGltf(path, fps);
}

} // namespace trimlab::ui
