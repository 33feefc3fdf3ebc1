#include "ui/design/session_recovery.h"

#include "ui/common/document.h"
#include "ui/design/design_workspace.h"

#include <QFileInfo>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>

namespace trimlab::ui {

namespace {

QString describe(const RecoverableSession& session)
{
    const QString project = !session.originalPath.isEmpty() ? QFileInfo(session.originalPath).fileName()
                            : !session.name.isEmpty()       ? session.name
                                                            : SessionRecovery::tr("an untitled project");
    return SessionRecovery::tr("Unsaved work on %1, autosaved %2.")
        .arg(project, QLocale().toString(session.savedAt.toLocalTime(), QLocale::ShortFormat));
}

} // namespace

SessionRecovery::SessionRecovery(QWidget* window, QSettings& settings, DesignWorkspace& workspace,
                                 ProjectFiles& projectFiles)
    : QObject(window),
      m_window(window),
      m_workspace(workspace),
      m_projectFiles(projectFiles),
      m_directory(settings.value(QStringLiteral("recovery/directory"), Autosave::defaultDirectory()).toString())
{
    m_autosave = std::make_unique<Autosave>(workspace, projectFiles, m_directory);
    m_autosave->setIntervalMinutes(
        settings.value(QStringLiteral("recovery/intervalMinutes"), Autosave::kDefaultIntervalMinutes).toInt());
    // An autosave that cannot be read stays where it is (the window reports the error);
    // the next start offers it again.
    connect(&projectFiles, &ProjectFiles::failed, this, [this](const QString& path, const QString&) {
        if (m_pending && path == m_pending->projectFile)
            m_pending.reset();
    });
}

SessionRecovery::~SessionRecovery() = default;

void SessionRecovery::offer()
{
    if (m_box || m_pending)
        return;
    const QList<RecoverableSession> sessions = Autosave::recoverableSessions(m_directory);
    if (sessions.isEmpty())
        return;
    const RecoverableSession session = sessions.front();
    m_box = new QMessageBox(QMessageBox::Question, tr("Recover unsaved work"),
                            tr("TrimLab did not close normally last time."), QMessageBox::NoButton, m_window);
    m_box->setObjectName(QStringLiteral("recoveryOffer"));
    QString details = describe(session);
    if (sessions.size() > 1)
        details +=
            QLatin1Char(' ') + tr("%n older session(s) can be recovered after this one.", "", int(sessions.size() - 1));
    m_box->setInformativeText(details + QLatin1Char('\n') + tr("Recover it? Discard deletes the autosaved copy."));
    QPushButton* recoverButton = m_box->addButton(tr("&Recover"), QMessageBox::AcceptRole);
    m_box->addButton(tr("&Discard"), QMessageBox::DestructiveRole);
    m_box->addButton(tr("&Not Now"), QMessageBox::RejectRole);
    m_box->setDefaultButton(recoverButton);
    m_box->setAttribute(Qt::WA_DeleteOnClose);
    m_box->setWindowModality(Qt::WindowModal);
    connect(m_box, &QMessageBox::buttonClicked, this,
            [this, session](QAbstractButton* button) { onOfferFinished(session, int(m_box->buttonRole(button))); });
    m_box->open();
}

void SessionRecovery::onOfferFinished(const RecoverableSession& session, int role)
{
    switch (QMessageBox::ButtonRole(role)) {
    case QMessageBox::AcceptRole:
        recover(session);
        break;
    case QMessageBox::DestructiveRole:
        Autosave::discard(session);
        break;
    default:
        return; // kept for the next start
    }
    if (!m_pending) // a discard: there may be more
        QMetaObject::invokeMethod(this, &SessionRecovery::offer, Qt::QueuedConnection);
}

void SessionRecovery::recover(const RecoverableSession& session)
{
    m_pending = session;
    m_projectFiles.open(session.projectFile);
}

bool SessionRecovery::adoptRecovered(const QString& path)
{
    if (!m_pending || QFileInfo(path).absoluteFilePath() != QFileInfo(m_pending->projectFile).absoluteFilePath())
        return false;
    const RecoverableSession session = *m_pending;
    m_pending.reset();
    if (Document* document = m_workspace.document()) {
        document->setName(session.name.isEmpty() ? tr("Untitled") : session.name);
        document->setFilePath(session.originalPath);
        document->markChanged(); // the recovered work is not in any project file yet
    }
    Autosave::discard(session);
    m_autosave->saveNow(); // protected again at once, under this process's name
    emit recovered(session.originalPath);
    return true;
}

} // namespace trimlab::ui
