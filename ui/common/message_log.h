#pragma once
/// \file
/// Every message the window gave — status lines and message boxes — with its time, the
/// history a status bar cannot keep: a long line is cut at the window's width, and the
/// next message replaces it within seconds. WindowContext records into it; the Messages
/// dock (ui/window/messages_panel.h) shows it. Oldest entries go beyond kMaxEntries.

#include <QDateTime>
#include <QObject>
#include <QString>

#include <cstddef>
#include <deque>

namespace trimlab::ui {

class MessageLog : public QObject {
    Q_OBJECT
public:
    enum class Kind { Status, Information, Warning, Error };

    struct Entry {
        QDateTime time;
        Kind kind = Kind::Status;
        QString text; ///< one message; a box's text and details on separate lines
    };

    static constexpr std::size_t kMaxEntries = 1000;

    explicit MessageLog(QObject* parent = nullptr);

    void add(Kind kind, const QString& text);
    [[nodiscard]] const std::deque<Entry>& entries() const { return m_entries; }
    void clear();

signals:
    void added(const trimlab::ui::MessageLog::Entry& entry);
    void cleared();

private:
    std::deque<Entry> m_entries;
};

/// "14:02:11  Warning  Could not open “x.obj”." (the time, the kind unless a status line,
/// the text).
[[nodiscard]] QString entryLine(const MessageLog::Entry& entry);

} // namespace trimlab::ui
