#include "ui/design/project_files.h"

#include "ui/common/background_job.h"
#include "ui/common/document.h"
#include "ui/common/task_progress_dialog.h"
#include "ui/design/design_session.h"
#include "ui/design/design_workspace.h"
#include "ui/common/last_directory.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QProgressDialog>
#include <QUndoStack>

#include <filesystem>
#include <stdexcept>

namespace trimlab::ui {

namespace {

void warnNotSaved(QWidget* parent, const QString& reason)
{
    QMessageBox box(QMessageBox::Warning, ProjectFiles::tr("Save Project"),
                    ProjectFiles::tr("The project was not saved."), QMessageBox::Ok, parent);
    box.setInformativeText(reason);
    box.exec();
}

} // namespace

ProjectFiles::ProjectFiles(QWidget* window, QSettings& settings, DesignWorkspace& workspace, ExtrasSource extras)
    : QObject(window),
      m_window(window),
      m_settings(settings),
      m_workspace(workspace),
      m_extras(std::move(extras)),
      m_task(new BackgroundJob<std::shared_ptr<const timeline::Project>>(this))
{
    connect(m_task, &BackgroundJobBase::succeeded, this, [this] { finishOpen(true, {}); });
    connect(m_task, &BackgroundJobBase::failed, this, [this](const QString& message) { finishOpen(false, message); });
    connect(m_task, &BackgroundJobBase::canceled, this, &ProjectFiles::closeProgress);
}

ProjectFiles::~ProjectFiles()
{
    closeProgress();
}

bool ProjectFiles::isProjectPath(const QString& path)
{
    return QFileInfo(path).suffix().compare(QLatin1String(kSuffix), Qt::CaseInsensitive) == 0;
}

QString ProjectFiles::dialogFilter()
{
    return tr("TrimLab project (*.%1)").arg(QLatin1String(kSuffix));
}

bool ProjectFiles::isOpening() const
{
    return m_task->isRunning();
}

void ProjectFiles::open(const QString& path)
{
    if (m_task->isRunning())
        m_task->cancel(); // its result is dropped; this request starts once it returned
    const auto start = [this, path] {
        m_openPath = path;
        const std::filesystem::path file = path.toStdString();
        m_task->start([file](const TaskControl&) {
            return std::make_shared<const timeline::Project>(timeline::readProject(file));
        });
        openTaskProgress(m_progress, m_window, m_task, tr("Opening project"),
                         tr("Reading %1…").arg(QFileInfo(path).fileName()));
    };
    if (m_task->isRunning())
        connect(m_task, &BackgroundJobBase::finished, this, start, Qt::SingleShotConnection);
    else
        start();
}

void ProjectFiles::finishOpen(bool succeeded, const QString& message)
{
    closeProgress();
    if (succeeded)
        emit opened(m_task->takeResult(), m_openPath);
    else
        emit failed(m_openPath, message);
}

void ProjectFiles::closeProgress()
{
    closeProgressDialog(m_progress);
}

bool ProjectFiles::canSave() const
{
    return m_workspace.session() || (m_sceneSource && m_sceneSource().scene);
}

QString ProjectFiles::currentPath() const
{
    const Document* document = m_workspace.document();
    return document ? document->filePath() : QString();
}

bool ProjectFiles::save()
{
    if (!canSave())
        return false;
    if (currentPath().isEmpty())
        return saveAs();
    QString error;
    if (saveTo(currentPath(), &error))
        return true;
    warnNotSaved(m_window, error);
    return false;
}

bool ProjectFiles::saveAs()
{
    if (!canSave())
        return false;
    const QString suggested =
        currentPath().isEmpty() ? loadSaveDirectory(m_settings) + QStringLiteral("/untitled.") + QLatin1String(kSuffix)
                                : currentPath();
    QString path = QFileDialog::getSaveFileName(m_window, tr("Save Project As"), suggested, dialogFilter());
    if (path.isEmpty())
        return false;
    if (!isProjectPath(path))
        path += QLatin1Char('.') + QLatin1String(kSuffix);
    saveLastDirectory(m_settings, QFileInfo(path).absolutePath());
    QString error;
    if (saveTo(path, &error))
        return true;
    warnNotSaved(m_window, error);
    return false;
}

bool ProjectFiles::saveTo(const QString& path, QString* error)
{
    QString reason;
    try {
        writeTo(path);
    } catch (const std::exception& e) {
        reason = QString::fromStdString(e.what());
    }
    if (error)
        *error = reason;
    if (!reason.isEmpty())
        return false;
    Document* document = m_workspace.document();
    if (document)
        document->markSaved(path);
    emit saved(document ? document->filePath() : QFileInfo(path).absoluteFilePath());
    emit saveableChanged();
    return true;
}

// The history with its extras, or the shown scene as a scene project: every object's
// mesh and placement, the CSG expression and per-object rules, and the extras.
void ProjectFiles::writeTo(const QString& path) const
{
    if (const DesignSession* session = m_workspace.session()) {
        timeline::saveProject(session->timeline(), path.toStdString(), m_extras());
        return;
    }
    const ShownScene shown = m_sceneSource ? m_sceneSource() : ShownScene{};
    if (!shown.scene)
        throw std::runtime_error(tr("There is no deformation history or scene to save.").toStdString());
    timeline::saveSceneProject(projectSceneOf(*shown.scene, shown.csg), path.toStdString(), m_extras());
}

bool ProjectFiles::maybeSave()
{
    const Document* document = m_workspace.document();
    if (!document || !document->isModified())
        return true;
    if (m_workspace.session() || !m_sceneSource || !m_sceneSource().scene)
        return askToSave(tr("The deformation history has changes that are not saved."),
                         tr("Save them to a project file first?"), QStringLiteral("unsavedHistoryBox"));
    const std::size_t objects = m_sceneSource().scene->scene.objects.size();
    return askToSave(tr("The scene of %1 objects has changes that are not saved.").arg(objects),
                     tr("Save its objects, placements and CSG to a project file first?"),
                     QStringLiteral("unsavedSceneBox"));
}

// Save (the default) / Discard / Cancel about unsaved work: true when the caller may go
// on (saved or discarded).
bool ProjectFiles::askToSave(const QString& text, const QString& question, const QString& name)
{
    QMessageBox box(QMessageBox::Warning, tr("Unsaved changes"), text,
                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, m_window);
    box.setObjectName(name);
    box.setInformativeText(question);
    box.setDefaultButton(QMessageBox::Save);
    switch (box.exec()) {
    case QMessageBox::Save:
        return save();
    case QMessageBox::Discard:
        return true;
    default:
        return false;
    }
}

} // namespace trimlab::ui
