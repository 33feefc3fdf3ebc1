#include "ui/design/history_exports.h"

#include "ui/common/background_job.h"
#include "ui/common/document.h"
#include "ui/common/task_progress_dialog.h"
#include "ui/design/design_session.h"
#include "ui/design/design_workspace.h"
#include "ui/common/last_directory.h"
#include "core/timeline/frame_export.h"
#include "core/timeline/stroke_replay.h"
#include "core/timeline/stroke_script.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QProgressDialog>
#include <QRegularExpression>

#include <filesystem>

namespace trimlab::ui {

namespace {

/// Runs `write`, turning an exception into `error`'s text; true when it returned.
template <class Write>
bool attempt(Write write, QString* error)
{
    QString reason;
    try {
        write();
    } catch (const std::exception& e) {
        reason = QString::fromStdString(e.what());
    }
    if (error)
        *error = reason;
    return reason.isEmpty();
}

} // namespace

HistoryExports::HistoryExports(QWidget* window, QSettings& settings, DesignWorkspace& workspace)
    : QObject(window),
      m_window(window),
      m_settings(settings),
      m_workspace(workspace),
      m_task(new BackgroundJob<std::shared_ptr<timeline::Timeline>>(this))
{
    connect(m_task, &BackgroundJobBase::succeeded, this, [this] { finishReplay(m_task->takeResult(), {}); });
    connect(m_task, &BackgroundJobBase::failed, this,
            [this](const QString& message) { finishReplay(nullptr, message); });
    connect(m_task, &BackgroundJobBase::canceled, this, [this] {
        closeProgress();
        emit statusMessage(tr("Replay canceled; the history is unchanged."));
    });
    connect(m_task, &BackgroundJobBase::progressed, this, [this](const QString&, qint64 done, qint64 total) {
        if (!m_progress)
            return;
        m_progress->setMaximum(int(total));
        m_progress->setValue(int(done));
    });
}

HistoryExports::~HistoryExports()
{
    closeProgress();
}

QString HistoryExports::suggestedPath(const QString& suffix) const
{
    const Document* document = m_workspace.document();
    const QString name = document && !document->filePath().isEmpty()
                             ? QFileInfo(document->filePath()).completeBaseName()
                             : QStringLiteral("deformation");
    return loadSaveDirectory(m_settings) + QLatin1Char('/') + name + suffix;
}

bool HistoryExports::exportObjSequence(const QString& directory, const QString& baseName, QString* error)
{
    const DesignSession* session = m_workspace.session();
    std::size_t written = 0;
    const bool ok = attempt(
        [&] {
            if (!session)
                throw std::runtime_error(tr("There is no deformation history.").toStdString());
            written = timeline::exportObjSequence(session->timeline(), directory.toStdString(), baseName.toStdString())
                          .size();
        },
        error);
    if (ok)
        emit statusMessage(tr("Wrote %n frame(s) to %1", nullptr, int(written)).arg(directory));
    return ok;
}

bool HistoryExports::exportGltf(const QString& path, double fps, QString* error)
{
    const DesignSession* session = m_workspace.session();
    const bool ok = attempt(
        [&] {
            if (!session)
                throw std::runtime_error(tr("There is no deformation history.").toStdString());
            timeline::exportMorphGltf(session->timeline(), path.toStdString(), fps);
        },
        error);
    if (ok)
        emit statusMessage(tr("Saved %1").arg(path));
    return ok;
}

bool HistoryExports::saveStrokeScript(const QString& path, QString* error)
{
    const DesignSession* session = m_workspace.session();
    const bool ok = attempt(
        [&] {
            if (!session)
                throw std::runtime_error(tr("There is no deformation history.").toStdString());
            timeline::writeStrokeScript(path.toStdString(), timeline::strokeScriptFromTimeline(session->timeline()));
        },
        error);
    if (ok)
        emit statusMessage(tr("Saved %1").arg(path));
    return ok;
}

void HistoryExports::showExportObjDialog()
{
    const QString path =
        QFileDialog::getSaveFileName(m_window, tr("Export Frames as OBJ Sequence"),
                                     suggestedPath(QStringLiteral("_0000.obj")), tr("OBJ sequence (*.obj)"));
    if (path.isEmpty())
        return;
    const QFileInfo info(path);
    saveLastDirectory(m_settings, info.absolutePath());
    QString baseName = info.completeBaseName();
    baseName.remove(QRegularExpression(QStringLiteral("_\\d+$"))); // the frame number is added per file
    QString error;
    if (!exportObjSequence(info.absolutePath(), baseName, &error))
        emit problem(tr("Export"), tr("The frames were not exported."), error);
}

void HistoryExports::showExportGltfDialog()
{
    QString path =
        QFileDialog::getSaveFileName(m_window, tr("Export Deformation as glTF"), suggestedPath(QStringLiteral(".glb")),
                                     tr("glTF binary (*.glb);;glTF (*.gltf)"));
    if (path.isEmpty())
        return;
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != QStringLiteral("glb") && suffix != QStringLiteral("gltf"))
        path += QStringLiteral(".glb");
    saveLastDirectory(m_settings, QFileInfo(path).absolutePath());
    QString error;
    if (!exportGltf(path, double(m_fps), &error))
        emit problem(tr("Export"), tr("The deformation was not exported."), error);
}

void HistoryExports::showSaveScriptDialog()
{
    QString path =
        QFileDialog::getSaveFileName(m_window, tr("Save Stroke Script"), suggestedPath(QStringLiteral("-strokes.json")),
                                     tr("Stroke script (*.json)"));
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".json");
    saveLastDirectory(m_settings, QFileInfo(path).absolutePath());
    QString error;
    if (!saveStrokeScript(path, &error))
        emit problem(tr("Save Stroke Script"), tr("The stroke script was not saved."), error);
}

void HistoryExports::showReplayDialog()
{
    const QString path = QFileDialog::getOpenFileName(m_window, tr("Replay Stroke Script"),
                                                      loadLastDirectory(m_settings), tr("Stroke script (*.json)"));
    if (path.isEmpty())
        return;
    saveLastDirectory(m_settings, QFileInfo(path).absolutePath());
    replay(path);
}

QProgressDialog* HistoryExports::progressDialog() const
{
    return m_progress.data();
}

bool HistoryExports::isReplaying() const
{
    return m_task->isRunning();
}

// Reading and replaying both run on the worker: a script may hold thousands of strokes.
void HistoryExports::replay(const QString& path)
{
    const DesignSession* session = m_workspace.session();
    if (!session) {
        emit problem(tr("Replay Stroke Script"), tr("There is no mesh to replay “%1” on.").arg(path),
                     tr("Open a closed mesh first."));
        return;
    }
    if (m_task->isRunning())
        return;
    m_replayPath = path;
    auto base = std::make_shared<const TriangleMesh>(session->timeline().base());
    const std::string file = path.toStdString();
    const std::string name = QFileInfo(path).fileName().toStdString();
    m_task->start([base, file, name](const TaskControl& control) {
        const timeline::StrokeScript script = timeline::loadStrokeScript(file);
        return std::make_shared<timeline::Timeline>(timeline::replayStrokeScript(*base, script, control, name));
    });
    m_progress = new QProgressDialog(tr("Replaying %1…").arg(QFileInfo(path).fileName()), tr("Cancel"), 0, 0, m_window);
    m_progress->setObjectName(QStringLiteral("replayProgressDialog"));
    m_progress->setWindowTitle(tr("Replay Stroke Script"));
    m_progress->setWindowModality(Qt::WindowModal);
    m_progress->setAutoClose(false);
    m_progress->setAutoReset(false);
    connect(m_progress, &QProgressDialog::canceled, m_task, &BackgroundJobBase::cancel);
    m_progress->setValue(0);
}

void HistoryExports::finishReplay(std::shared_ptr<timeline::Timeline> result, const QString& message)
{
    closeProgress();
    const bool succeeded = result != nullptr;
    const DesignSession* session = m_workspace.session();
    const bool sameMesh = session && result && session->timeline().base() == result->base();
    if (!succeeded || !sameMesh) {
        emit problem(tr("Replay Stroke Script"), tr("Could not replay “%1”.").arg(QFileInfo(m_replayPath).fileName()),
                     succeeded ? tr("Another mesh was opened during the replay.") : message);
        return;
    }
    const int strokes = result->frameCount() - 1;
    const glm::dmat4 model = session->modelMatrix(); // a copy: startSession replaces the session
    m_workspace.startSession(std::move(*result), model);
    // The replayed history is a change of the document that no file holds yet.
    if (Document* document = m_workspace.document())
        document->markChanged();
    emit statusMessage(tr("Replayed %n stroke(s) from %1.", nullptr, strokes).arg(QFileInfo(m_replayPath).fileName()));
    emit replayed(m_replayPath);
}

void HistoryExports::closeProgress()
{
    closeProgressDialog(m_progress);
}

} // namespace trimlab::ui
