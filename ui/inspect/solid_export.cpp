#include "ui/inspect/solid_export.h"

#include "ui/common/background_job.h"
#include "ui/common/task_progress_dialog.h"
#include "ui/common/window_context.h"

#include "core/mesh/mesh_export.h"
#include "core/mesh/mesh_sequence_gltf.h"
#include "core/solid/trimmed_animation.h"
#include "core/trim/static_rule.h"

#include <QFileInfo>
#include <QMainWindow>
#include <QMessageBox>
#include <QPushButton>

#include <optional>

namespace trimlab::ui {

SolidExport::SolidExport(const WindowContext& context, ShownSource shown, QObject* parent)
    : QObject(parent), m_context(context), m_shown(std::move(shown)), m_task(new BackgroundJob<Written>(this))
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

namespace {

// Which of an animation's poses to export: the one shown or all of them; nullopt when
// the user cancels.
std::optional<bool> askAllPoses(QWidget* parent, const SolidExport::Shown& shown)
{
    QMessageBox ask(QMessageBox::Question, SolidExport::tr("Export Trimmed Solid"),
                    SolidExport::tr("Export the trimmed solid of the pose shown (pose %1), or of every pose of the "
                                    "animation (%2 poses, each trimmed on its own) as one glTF that plays them?")
                        .arg(shown.pose)
                        .arg(shown.animation->poseCount()),
                    QMessageBox::Cancel, parent);
    ask.setObjectName(QStringLiteral("exportPosesBox"));
    QPushButton* one = ask.addButton(SolidExport::tr("This Pose"), QMessageBox::AcceptRole);
    one->setObjectName(QStringLiteral("exportThisPoseButton"));
    QPushButton* all = ask.addButton(SolidExport::tr("All Poses (glTF)"), QMessageBox::AcceptRole);
    all->setObjectName(QStringLiteral("exportAllPosesButton"));
    ask.setDefaultButton(one);
    ask.exec();
    if (ask.clickedButton() != one && ask.clickedButton() != all)
        return std::nullopt;
    return ask.clickedButton() == all;
}

} // namespace

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
    bool allPoses = false;
    if (shown.animation && shown.animation->poseCount() > 1) {
        const std::optional<bool> answer = askAllPoses(&m_context.window(), shown);
        if (!answer)
            return;
        allPoses = *answer;
    }
    const QString base = shown.name.isEmpty() ? QStringLiteral("trimmed") : shown.name + QStringLiteral("-trimmed");
    const QString cut = extent == Extent::AsShown ? QStringLiteral("-cut") : QString();
    if (allPoses) {
        const QString path =
            m_context.askSavePath(tr("Export Trimmed Poses"), {tr("glTF binary (*.glb)"), tr("glTF (*.gltf)")},
                                  base + cut + QStringLiteral("-poses.glb"));
        if (!path.isEmpty())
            exportPosesTo(path, extent);
        return;
    }
    const QString path =
        m_context.askSavePath(tr("Export Trimmed Solid"),
                              {tr("Wavefront OBJ (*.obj)"), tr("PLY, binary (*.ply)"), tr("STL, binary (*.stl)"),
                               tr("glTF binary (*.glb)"), tr("glTF (*.gltf)")},
                              base + cut + QStringLiteral(".obj"));
    if (!path.isEmpty())
        exportTo(path, extent);
}

bool SolidExport::refused(const Shown& shown, const QString& path)
{
    if (shown.refusal.isEmpty() && !m_task->isRunning())
        return false;
    const QString reason = !shown.refusal.isEmpty() ? shown.refusal : tr("An export is already running.");
    m_context.showMessage(QMessageBox::Information, tr("Export Trimmed Solid"), reason, shown.remedy);
    emit failed(path, shown.remedy.isEmpty() ? reason : reason + QLatin1Char(' ') + shown.remedy);
    return true;
}

void SolidExport::exportTo(const QString& path, Extent extent)
{
    const Shown shown = m_shown();
    if (refused(shown, path))
        return;
    m_path = path;
    const std::string comment = shown.name.toStdString() + " trimmed by " + ruleName(shown.settings.rule) +
                                (extent == Extent::AsShown ? ", cut by the clipping planes and capped" : "");
    m_task->start([scene = shown.scene, settings = shown.settings, file = path.toStdString(), comment,
                   extent](const TaskControl& control) {
        const TrimmedSolid solid = extent == Extent::AsShown ? cutTrimmedSolid(*scene, settings, control)
                                                             : trimmedSolid(*scene, settings, control);
        control.throwIfCancelled();
        saveTriangleMesh(file, solid.mesh, comment);
        return Written{solid.stats, 0, solid.stats.signedVolume};
    });
    openTaskProgress(m_progress, &m_context.window(), m_task, tr("Export Trimmed Solid"),
                     tr("Computing the trimmed solid of %1…").arg(shown.name));
}

void SolidExport::exportPosesTo(const QString& path, Extent extent)
{
    Shown shown = m_shown();
    if (!shown.animation && shown.refusal.isEmpty()) {
        shown.refusal = tr("No animation is shown, so there are no poses to export.");
        shown.remedy = tr("Open an animation (File ▸ Open Animation) first.");
    }
    if (refused(shown, path))
        return;
    m_path = path;
    TrimSettings settings = shown.settings;
    if (extent == Extent::Whole)
        settings.setClipSet(ClipSet{}); // trimAnimationPoses cuts by whatever planes are enabled
    const std::string comment = shown.name.toStdString() + " trimmed pose by pose by " + ruleName(settings.rule) +
                                (extent == Extent::AsShown ? ", cut by the clipping planes and capped" : "");
    m_task->start([animation = shown.animation, settings, file = path.toStdString(), comment,
                   fps = shown.fps](const TaskControl& control) {
        std::vector<SequenceMesh> meshes;
        Written written;
        trimAnimationPoses(
            *animation, 0, animation->poseCount() - 1, settings,
            [&](std::size_t pose, const TrimmedSolid& solid) {
                meshes.push_back({trimmedPoseName(pose), solid.mesh});
                written.stats = solid.stats;
                written.totalVolume += solid.stats.signedVolume;
            },
            control);
        control.throwIfCancelled();
        saveMeshSequenceGltf(file, meshes, 1.0 / fps, comment);
        written.poses = meshes.size();
        return written;
    });
    openTaskProgress(m_progress, &m_context.window(), m_task, tr("Export Trimmed Poses"),
                     tr("Trimming every pose of %1…").arg(shown.name));
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
    const Written& written = m_task->result();
    if (written.poses > 0) {
        m_context.showStatus(tr("Exported %1 trimmed poses to %2 (one node per pose, shown in turn); total volume %3")
                                 .arg(written.poses)
                                 .arg(m_path)
                                 .arg(written.totalVolume, 0, 'g', 6));
        emit posesExported(m_path, written.poses, written.totalVolume);
        return;
    }
    const TrimmedSolidStats& stats = written.stats;
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
