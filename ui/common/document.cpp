#include "ui/common/document.h"

#include <QFileInfo>
#include <QUndoStack>

namespace trimlab::ui {

Document::Document(Kind kind, QString name, timeline::DocumentSettings settings, QString filePath, QObject* parent)
    : QObject(parent),
      m_kind(kind),
      m_name(std::move(name)),
      m_filePath(filePath.isEmpty() ? QString() : QFileInfo(filePath).absoluteFilePath()),
      m_settings(std::move(settings)),
      m_undo(new QUndoStack(this))
{
    m_undo->setObjectName(QStringLiteral("documentUndoStack"));
    connect(m_undo, &QUndoStack::cleanChanged, this, &Document::reportModified);
    connect(m_undo, &QUndoStack::indexChanged, this, [this] { ++m_revision; });
}

Document::~Document() = default;

QString Document::title() const
{
    return m_filePath.isEmpty() ? m_name : QFileInfo(m_filePath).fileName();
}

void Document::setName(const QString& name)
{
    if (name == m_name)
        return;
    m_name = name;
    if (m_filePath.isEmpty())
        emit titleChanged();
}

void Document::setFilePath(const QString& path)
{
    const QString absolute = path.isEmpty() ? QString() : QFileInfo(path).absoluteFilePath();
    if (absolute == m_filePath)
        return;
    m_filePath = absolute;
    emit titleChanged();
}

void Document::setSettings(const timeline::DocumentSettings& settings)
{
    if (settings == m_settings)
        return;
    m_settings = settings;
    emit settingsChanged();
}

bool Document::isModified() const
{
    return m_changed || !m_undo->isClean();
}

void Document::markChanged()
{
    m_changed = true;
    ++m_revision;
    reportModified();
}

void Document::markSaved(const QString& path)
{
    m_changed = false;
    m_undo->setClean();
    setFilePath(path);
    reportModified();
}

void Document::reportModified()
{
    const bool modified = isModified();
    if (modified == m_reportedModified)
        return;
    m_reportedModified = modified;
    emit modifiedChanged(modified);
}

} // namespace trimlab::ui
