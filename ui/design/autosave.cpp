#include "ui/design/autosave.h"

#include "ui/common/current_document.h"
#include "ui/common/document.h"
#include "ui/design/design_workspace.h"

#include "core/io/atomic_write.h"
#include "core/timeline/project_file.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLockFile>
#include <QStandardPaths>
#include <QTimer>

#include <algorithm>

namespace trimlab::ui {

namespace {

constexpr int kMillisecondsPerMinute = 60 * 1000;
const QString kPrefix = QStringLiteral("session-");

QString infoJson(const Document& document)
{
    QJsonObject info;
    info.insert(QStringLiteral("projectPath"), document.filePath());
    info.insert(QStringLiteral("name"), document.title());
    info.insert(QStringLiteral("savedAt"), QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs));
    return QString::fromUtf8(QJsonDocument(info).toJson());
}

// Reads the companion JSON; a missing or damaged one leaves the fields empty (the
// autosaved project is what matters and is still offered).
void readInfo(RecoverableSession& session)
{
    QFile file(session.infoFile);
    if (!file.open(QIODevice::ReadOnly))
        return;
    const QJsonObject info = QJsonDocument::fromJson(file.readAll()).object();
    session.originalPath = info.value(QStringLiteral("projectPath")).toString();
    session.name = info.value(QStringLiteral("name")).toString();
    session.savedAt = QDateTime::fromString(info.value(QStringLiteral("savedAt")).toString(), Qt::ISODateWithMs);
}

// True when nobody holds the lock any more: its process died (QLockFile removes such a
// stale lock and takes it). The lock is released again at once; discard() or the next
// start deals with the files.
bool ownerIsGone(const QString& lockPath)
{
    QLockFile lock(lockPath);
    lock.setStaleLockTime(0); // only a dead owner makes a lock stale, never its age
    if (!lock.tryLock(0))
        return false;
    lock.unlock();
    return true;
}

} // namespace

QString Autosave::defaultDirectory()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) + QStringLiteral("/recovery");
}

Autosave::Autosave(DesignWorkspace& workspace, const ProjectFiles& files, QString directory, QObject* parent)
    : QObject(parent),
      m_workspace(workspace),
      m_files(files),
      m_directory(std::move(directory)),
      m_timer(new QTimer(this))
{
    if (!QDir().mkpath(m_directory)) {
        m_lastError = tr("Autosave is off: cannot create the recovery folder %1.").arg(m_directory);
    } else {
        m_lock = std::make_unique<QLockFile>(sessionFile(QStringLiteral(".lock")));
        m_lock->setStaleLockTime(0); // held for the whole session
        if (!m_lock->tryLock(0)) {
            m_lastError = tr("Autosave is off: cannot lock %1.").arg(sessionFile(QStringLiteral(".lock")));
            m_lock.reset();
        }
    }
    connect(m_timer, &QTimer::timeout, this, &Autosave::saveNow);
    connect(&m_workspace.currentDocument(), &CurrentDocument::modifiedChanged, this, &Autosave::onModifiedChanged);
    setIntervalMinutes(kDefaultIntervalMinutes);
}

Autosave::~Autosave()
{
    clear();
}

void Autosave::setIntervalMinutes(int minutes)
{
    m_intervalMinutes = std::max(0, minutes);
    if (m_intervalMinutes == 0)
        m_timer->stop();
    else
        m_timer->start(m_intervalMinutes * kMillisecondsPerMinute);
}

QString Autosave::sessionFile(const QString& suffix) const
{
    return m_directory + QLatin1Char('/') + kPrefix + QString::number(QCoreApplication::applicationPid()) + suffix;
}

QString Autosave::recoveryProjectPath() const
{
    return sessionFile(QStringLiteral(".") + QLatin1String(ProjectFiles::kSuffix));
}

bool Autosave::saveNow()
{
    const Document* document = m_workspace.document();
    if (!m_lock || !document || !m_files.canSave())
        return false;
    if (!document->isModified()) {
        clear(); // the project file holds everything
        return false;
    }
    if (document == m_savedDocument && document->revision() == m_savedRevision)
        return false;
    try {
        m_files.writeTo(recoveryProjectPath());
        io::writeFileAtomically(sessionFile(QStringLiteral(".json")).toStdString(), infoJson(*document).toStdString());
    } catch (const std::exception& e) {
        m_lastError = tr("Autosave failed: %1").arg(QString::fromStdString(e.what()));
        emit failed(m_lastError);
        return false;
    }
    m_savedDocument = document;
    m_savedRevision = document->revision();
    emit autosaved(recoveryProjectPath());
    return true;
}

void Autosave::clear()
{
    if (!m_lock)
        return;
    QFile::remove(recoveryProjectPath());
    QFile::remove(sessionFile(QStringLiteral(".json")));
    m_savedDocument = nullptr;
    m_savedRevision = 0;
}

void Autosave::onModifiedChanged(bool modified)
{
    if (!modified)
        clear();
}

QList<RecoverableSession> Autosave::recoverableSessions(const QString& directory)
{
    QList<RecoverableSession> sessions;
    const QString ownName = kPrefix + QString::number(QCoreApplication::applicationPid()) + QLatin1Char('.');
    const QDir dir(directory);
    const QStringList projects =
        dir.entryList({kPrefix + QStringLiteral("*.") + QLatin1String(ProjectFiles::kSuffix)}, QDir::Files);
    for (const QString& name : projects) {
        if (name.startsWith(ownName))
            continue;
        const QString stem = dir.filePath(QFileInfo(name).completeBaseName());
        RecoverableSession session;
        session.projectFile = dir.filePath(name);
        session.infoFile = stem + QStringLiteral(".json");
        session.lockFile = stem + QStringLiteral(".lock");
        if (!ownerIsGone(session.lockFile))
            continue;
        readInfo(session);
        if (!session.savedAt.isValid())
            session.savedAt = QFileInfo(session.projectFile).lastModified();
        sessions.push_back(session);
    }
    std::sort(sessions.begin(), sessions.end(),
              [](const RecoverableSession& a, const RecoverableSession& b) { return a.savedAt > b.savedAt; });
    return sessions;
}

void Autosave::discard(const RecoverableSession& session)
{
    QFile::remove(session.projectFile);
    QFile::remove(session.infoFile);
    QFile::remove(session.lockFile);
}

} // namespace trimlab::ui
