#include "ui/skinning/skinning_workspace.h"

#include "ui/common/window_context.h"
#include "ui/skinning/skinning_panel.h"
#include "ui/skinning/skinning_session.h"

#include <QDockWidget>
#include <QMainWindow>
#include <QMessageBox>
#include <QPushButton>
#include <QUndoStack>

namespace trimlab::ui {

SkinningWorkspace::SkinningWorkspace(const WindowContext& context, QDockWidget* tabWith, QObject* parent)
    : QObject(parent), m_context(context), m_panel(new SkinningPanel)
{
    m_dock = m_context.addSideDock(tr("Skinning"), QStringLiteral("skinningDock"), m_panel, tabWith);
    m_dock->hide(); // shown while an animation is open
    connect(m_panel, &SkinningPanel::exportRequested, this, &SkinningWorkspace::exportRequested);
    connect(m_panel, &SkinningPanel::exportFinished, this,
            [this](const QString& path, double eRms, const QString& kind) {
                // The file holds the edits as they were when the export started: those are saved.
                SkinningSession* session = m_panel->session();
                if (session && session->undoStack()->index() == m_exportIndex)
                    session->undoStack()->setClean();
                m_exportIndex = -1;
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
    const QString path =
        m_context.askSavePath(tr("Export Skinning"), {tr("glTF (*.gltf)"), tr("Binary glTF (*.glb)")},
                              m_context.sceneBaseName(QStringLiteral("animation")) + QStringLiteral("-skinned.gltf"));
    if (path.isEmpty())
        return;
    SkinningSession* session = m_panel->session();
    m_exportIndex = session ? session->undoStack()->index() : -1;
    m_panel->exportGltf(path, fps);
}

bool SkinningWorkspace::hasUnexportedEdits() const
{
    SkinningSession* session = m_panel->session();
    return session && !session->undoStack()->isClean();
}

bool SkinningWorkspace::confirmDiscardEdits(double fps)
{
    if (!hasUnexportedEdits())
        return true;
    QMessageBox box(QMessageBox::Warning, tr("Unexported skinning edits"),
                    tr("The skinning approximation has bone edits that were not exported."),
                    QMessageBox::Discard | QMessageBox::Cancel, &m_context.window());
    box.setObjectName(QStringLiteral("unexportedSkinningEditsBox"));
    box.setInformativeText(tr("Opening another file or closing TrimLab discards them. Export them as a skinned "
                              "glTF first?"));
    QPushButton* exportButton = box.addButton(tr("Export…"), QMessageBox::AcceptRole);
    box.setDefaultButton(exportButton);
    box.exec();
    if (box.clickedButton() == exportButton) {
        m_dock->raise();
        showExportDialog(fps);
        return false;
    }
    return box.clickedButton() == box.button(QMessageBox::Discard);
}

} // namespace trimlab::ui
