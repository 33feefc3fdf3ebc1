#include "ui/common/scene_loader.h"
#include "ui/common/task_progress_dialog.h"

#include "core/mesh/mesh_load_error.h"

#include <QFileInfo>
#include <QFutureWatcher>
#include <QProgressDialog>
#include <QtConcurrent/QtConcurrentRun>

#include <new>

namespace trimlab::ui {

namespace {

/// What a worker hands back: the scene, or the reason it could not be loaded.
struct LoadOutcome {
    std::shared_ptr<const LoadedScene> scene;
    QString error;
};

/// Runs on a worker thread; never throws (exceptions do not cross QtConcurrent::run).
LoadOutcome loadOnWorker(const std::string& source)
{
    try {
        return {std::make_shared<const LoadedScene>(loadScene(source)), {}};
    } catch (const MeshLoadError& e) {
        return {nullptr, QString::fromStdString(e.what())};
    } catch (const std::bad_alloc&) {
        return {nullptr, QObject::tr("Not enough memory to load %1.").arg(QString::fromStdString(source))};
    } catch (const std::exception& e) {
        return {nullptr, QString::fromStdString(e.what())};
    }
}

QString displayNameOf(const QString& source)
{
    if (isDemoSource(source.toStdString()))
        return source;
    const QString name = QFileInfo(source).fileName();
    return name.isEmpty() ? source : name;
}

} // namespace

SceneLoader::SceneLoader(QWidget* dialogParent) : QObject(dialogParent), m_dialogParent(dialogParent)
{
}

SceneLoader::~SceneLoader()
{
    closeProgress();
}

void SceneLoader::load(const QString& source)
{
    closeProgress();
    const quint64 generation = ++m_generation;
    m_source = source;
    m_pending = true;
    auto* watcher = new QFutureWatcher<LoadOutcome>(this);
    connect(watcher, &QFutureWatcher<LoadOutcome>::finished, this, [this, watcher, generation] {
        const LoadOutcome outcome = watcher->result();
        finish(outcome.scene, outcome.error, generation);
        watcher->deleteLater();
    });
    watcher->setFuture(QtConcurrent::run(loadOnWorker, source.toStdString()));
    showProgress(source);
}

QProgressDialog* SceneLoader::progressDialog() const
{
    return m_progress.data();
}

void SceneLoader::cancel()
{
    if (!m_pending)
        return;
    ++m_generation; // the running worker's result no longer matches
    m_pending = false;
    closeProgress();
    emit canceled(m_source);
}

void SceneLoader::finish(std::shared_ptr<const LoadedScene> scene, const QString& error, quint64 generation)
{
    if (generation != m_generation || !m_pending)
        return; // canceled or superseded: drop the result
    m_pending = false;
    closeProgress();
    if (scene)
        emit loaded(std::move(scene));
    else
        emit failed(m_source, error);
}

void SceneLoader::showProgress(const QString& source)
{
    // Range 0..0 is a busy indicator. The dialog shows itself once the minimum duration
    // has passed since a setValue(minimum), which starts that clock.
    m_progress = new QProgressDialog(tr("Loading %1…").arg(displayNameOf(source)), tr("Cancel"), 0, 0, m_dialogParent);
    m_progress->setWindowTitle(tr("Opening"));
    m_progress->setWindowModality(Qt::WindowModal);
    m_progress->setAutoClose(false);
    m_progress->setAutoReset(false);
    m_progress->setMinimumDuration(m_progressDelayMs);
    connect(m_progress, &QProgressDialog::canceled, this, &SceneLoader::cancel);
    m_progress->setValue(0);
}

void SceneLoader::closeProgress()
{
    closeProgressDialog(m_progress);
}

} // namespace trimlab::ui
