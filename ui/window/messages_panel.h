#pragma once
/// \file
/// View ▸ Messages: the window's message log (ui/common/message_log.h) as a list, oldest
/// first, warnings and errors marked, each line whole (a tooltip for a line wider than
/// the dock). The window puts it in a bottom dock, hidden until asked for; a click on the
/// status bar opens it, so a message cut off there can be read in full.

#include "ui/common/message_log.h"

#include <QWidget>

class QListWidget;

namespace trimlab::ui {

class MessagesPanel : public QWidget {
    Q_OBJECT
public:
    explicit MessagesPanel(MessageLog& log, QWidget* parent = nullptr);

    /// The lines shown, oldest first.
    [[nodiscard]] QStringList lines() const;

private:
    void append(const MessageLog::Entry& entry);

    MessageLog& m_log;
    QListWidget* m_list = nullptr;
};

} // namespace trimlab::ui
