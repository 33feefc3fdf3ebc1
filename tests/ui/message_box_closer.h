#pragma once
/// \file
/// Test helper: closes every message box that appears, as a user pressing Return would,
/// and remembers "text\ninformative text" of each. Works for boxes opened with open()
/// and for modal exec() ones (its timer runs inside their event loop).

#include <QAbstractButton>
#include <QApplication>
#include <QMessageBox>
#include <QStringList>
#include <QTimer>
#include <QtTest>

namespace trimlab::test {

class MessageBoxCloser : public QObject {
public:
    explicit MessageBoxCloser(int intervalMs = 20)
    {
        connect(&m_timer, &QTimer::timeout, this, &MessageBoxCloser::closeVisibleBoxes);
        m_timer.start(intervalMs);
    }
    [[nodiscard]] const QStringList& seen() const { return m_seen; }

private:
    void closeVisibleBoxes()
    {
        for (QWidget* widget : QApplication::topLevelWidgets()) {
            auto* box = qobject_cast<QMessageBox*>(widget);
            if (box && box->isVisible()) {
                m_seen << box->text() + QLatin1Char('\n') + box->informativeText();
                QTest::keyClick(box, Qt::Key_Return);
            }
        }
    }

    QTimer m_timer;
    QStringList m_seen;
};

/// Test helper: answers every message box that appears by clicking its `button`, as a
/// user choosing Discard or Cancel would, and remembers "text\ninformative text" and the
/// object name of each.
class MessageBoxAnswerer : public QObject {
public:
    explicit MessageBoxAnswerer(QMessageBox::StandardButton button, int intervalMs = 20) : m_button(button)
    {
        connect(&m_timer, &QTimer::timeout, this, &MessageBoxAnswerer::answerVisibleBoxes);
        m_timer.start(intervalMs);
    }
    [[nodiscard]] const QStringList& seen() const { return m_seen; }
    [[nodiscard]] const QStringList& names() const { return m_names; }

private:
    void answerVisibleBoxes()
    {
        for (QWidget* widget : QApplication::topLevelWidgets()) {
            auto* box = qobject_cast<QMessageBox*>(widget);
            if (!box || !box->isVisible())
                continue;
            m_seen << box->text() + QLatin1Char('\n') + box->informativeText();
            m_names << box->objectName();
            if (QAbstractButton* answer = box->button(m_button))
                answer->click();
            else
                QTest::keyClick(box, Qt::Key_Escape);
        }
    }

    QMessageBox::StandardButton m_button;
    QTimer m_timer;
    QStringList m_seen;
    QStringList m_names;
};

} // namespace trimlab::test
