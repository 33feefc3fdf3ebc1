#include "ui/common/message_log.h"

namespace trimlab::ui {

MessageLog::MessageLog(QObject* parent) : QObject(parent)
{
}

void MessageLog::add(Kind kind, const QString& text)
{
    if (text.trimmed().isEmpty())
        return;
    m_entries.push_back({QDateTime::currentDateTime(), kind, text});
    while (m_entries.size() > kMaxEntries)
        m_entries.pop_front();
    emit added(m_entries.back());
}

void MessageLog::clear()
{
    m_entries.clear();
    emit cleared();
}

QString entryLine(const MessageLog::Entry& entry)
{
    QString kind;
    switch (entry.kind) {
    case MessageLog::Kind::Status:
        break;
    case MessageLog::Kind::Information:
        kind = MessageLog::tr("Note");
        break;
    case MessageLog::Kind::Warning:
        kind = MessageLog::tr("Warning");
        break;
    case MessageLog::Kind::Error:
        kind = MessageLog::tr("Error");
        break;
    }
    const QString time = entry.time.toString(QStringLiteral("HH:mm:ss"));
    return kind.isEmpty() ? time + QStringLiteral("  ") + entry.text
                          : time + QStringLiteral("  ") + kind + QStringLiteral("  ") + entry.text;
}

} // namespace trimlab::ui
