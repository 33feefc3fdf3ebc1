#include "ui/window/messages_panel.h"

#include <QHBoxLayout>
#include <QListWidget>
#include <QPushButton>
#include <QStyle>
#include <QVBoxLayout>

namespace trimlab::ui {

MessagesPanel::MessagesPanel(MessageLog& log, QWidget* parent) : QWidget(parent), m_log(log)
{
    setObjectName(QStringLiteral("messagesPanel"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    m_list = new QListWidget(this);
    m_list->setObjectName(QStringLiteral("messagesList"));
    m_list->setWordWrap(true);
    m_list->setSelectionMode(QAbstractItemView::ExtendedSelection);
    layout->addWidget(m_list, 1);
    auto* side = new QVBoxLayout;
    auto* clear = new QPushButton(tr("Clear"), this);
    clear->setObjectName(QStringLiteral("clearMessagesButton"));
    clear->setToolTip(tr("Forget the messages shown so far"));
    side->addWidget(clear);
    side->addStretch(1);
    layout->addLayout(side);
    for (const MessageLog::Entry& entry : m_log.entries())
        append(entry);
    connect(&m_log, &MessageLog::added, this, &MessagesPanel::append);
    connect(&m_log, &MessageLog::cleared, m_list, &QListWidget::clear);
    connect(clear, &QPushButton::clicked, &m_log, &MessageLog::clear);
}

QStringList MessagesPanel::lines() const
{
    QStringList lines;
    for (int i = 0; i < m_list->count(); ++i)
        lines << m_list->item(i)->text();
    return lines;
}

void MessagesPanel::append(const MessageLog::Entry& entry)
{
    if (m_list->count() >= int(MessageLog::kMaxEntries))
        delete m_list->takeItem(0);
    auto* item = new QListWidgetItem(entryLine(entry), m_list);
    item->setToolTip(entry.text);
    if (entry.kind == MessageLog::Kind::Error)
        item->setIcon(style()->standardIcon(QStyle::SP_MessageBoxCritical));
    else if (entry.kind == MessageLog::Kind::Warning)
        item->setIcon(style()->standardIcon(QStyle::SP_MessageBoxWarning));
    m_list->scrollToBottom();
}

} // namespace trimlab::ui
