#include "ui/inspect/solid_export.h"

#include "ui/common/background_job.h"
#include "ui/common/task_progress_dialog.h"
#include "ui/common/window_context.h"

#include "core/mesh/mesh_export.h"
#include "core/trim/static_rule.h"

#include <QFileInfo>
#include <QMainWindow>
#include <QMessageBox>
#include <QPushButton>

namespace trimlab::ui {

SolidExport::SolidExport(const WindowContext& context, ShownSource shown, QObject* parent)
    : QObject(parent), m_context(context), m_shown(std::move(shown)), m_task(new BackgroundJob<TrimmedSolidStats>(this))
{
    connect(m_task, &BackgroundJobBase::succeeded, this, [this] { finish(true, {}); });
    connect(m_task, &BackgroundJobBase::failed, this, [this](const QString& message) { finish(false, message); });
    connect(m_task, &BackgroundJobBase::canceled, this, [this] {
        closeProgress();
        m_context.showStatus(tr("Export of the trimmed solid canceled."));
    });
}

SolidExport::~SolidExport()
{
    closeProgress();
}

bool SolidExport::isExporting() const
{
    return m_task->isRunning();
}

void SolidExport::showExportDialog()
{
    const Shown shown = m_shown();
    if (!shown.refusal.isEmpty()) {
        m_context.showMessage(QMessageBox::Information, tr("Export Trimmed Solid"), shown.refusal, shown.remedy);
        return;
    }
    Extent extent = Extent::Whole;
    if (shown.settings.clipSet().anyEnabled()) {
        QMessageBox ask(QMessageBox::Question, tr("Export Trimmed Solid"),
                        tr("Clipping planes cut the view. Export the solid as shown, cut by the planes and closed by "
                           "caps on them, or the whole solid?"),
                        QMessageBox::Cancel, &m_context.window());
        ask.setObjectName(QStringLiteral("exportExtentBox"));
        QPushButton* asShown = ask.addButton(tr("As Shown (Cut and Capped)"), QMessageBox::AcceptRole);
        asShown->setObjectName(QStringLiteral("exportAsShownButton"));
        ask.addButton(tr("Whole Solid"), QMessageBox::AcceptRole)->setObjectName(QStringLiteral("exportWholeButton"));
        ask.setDefaultButton(asShown);
        ask.exec();
        if (ask.clickedButton() == nullptr || ask.clickedButton() == ask.button(QMessageBox::Cancel))
            return;
        extent = ask.clickedButton() == asShown ? Extent::AsShown : Extent::Whole;
    }
    const QString base = shown.name.isEmpty() ? QStringLiteral("trimmed") : shown.name + QStringLiteral("-trimmed");
    const QString path =
        m_context.askSavePath(tr("Export Trimmed Solid"),
                              {tr("Wavefront OBJ (*.obj)"), tr("PLY, binary (*.ply)"), tr("STL, binary (*.stl)"),
                               tr("glTF binary (*.glb)"), tr("glTF (*.gltf)")},
                              base + (extent == Extent::AsShown ? QStringLiteral("-cut.obj") : QStringLiteral(".obj")));
    if (!path.isEmpty())
        exportTo(path, extent);
}

void SolidExport::exportTo(const QString& path, Extent extent)
{
    const Shown shown = m_shown();
    if (!shown.refusal.isEmpty() || m_task->isRunning()) {
        const QString reason = !shown.refusal.isEmpty() ? shown.refusal : tr("An export is already running.");
        m_context.showMessage(QMessageBox::Information, tr("Export Trimmed Solid"), reason, shown.remedy);
        emit failed(path, shown.remedy.isEmpty() ? reason : reason + QLatin1Char(' ') + shown.remedy);
        return;
    }
    m_path = path;
    const std::string comment = shown.name.toStdString() + " trimmed by " + ruleName(shown.settings.rule) +
                                (extent == Extent::AsShown ? ", cut by the clipping planes and capped" : "");
    m_task->start([scene = shown.scene, settings = shown.settings, file = path.toStdString(), comment,
                   extent](const TaskControl& control) {
        const TrimmedSolid solid = extent == Extent::AsShown ? cutTrimmedSolid(*scene, settings, control)
                                                             : trimmedSolid(*scene, settings, control);
        control.throwIfCancelled();
        saveTriangleMesh(file, solid.mesh, comment);
        return solid.stats;
    });
    openTaskProgress(m_progress, &m_context.window(), m_task, tr("Export Trimmed Solid"),
                     tr("Computing the trimmed solid of %1…").arg(shown.name));
}

void SolidExport::finish(bool succeeded, const QString& message)
{
    closeProgress();
    if (!succeeded) {
        m_context.showMessage(QMessageBox::Warning, tr("Export Trimmed Solid"),
                              tr("The trimmed solid was not exported to “%1”.").arg(QFileInfo(m_path).fileName()),
                              message);
        emit failed(m_path, message);
        return;
    }
    const TrimmedSolidStats& stats = m_task->result();
    QString text = tr("Exported the trimmed solid to %1: %2 triangles, volume %3")
                       .arg(m_path)
                       .arg(stats.keptFaces - stats.roundingDroppedFaces)
                       .arg(stats.signedVolume, 0, 'g', 6);
    if (stats.nonManifoldEdges > 0)
        text += tr(" (%1 edges where kept cells touch: not manifold there)").arg(stats.nonManifoldEdges);
    m_context.showStatus(text);
    emit exported(m_path, stats);
}

void SolidExport::closeProgress()
{
    closeProgressDialog(m_progress);
}

} // namespace trimlab::ui
