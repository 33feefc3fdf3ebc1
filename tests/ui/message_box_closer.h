#pragma once
/// \file
/// Test helper: closes every message box that appears, as a user pressing Return would,
/// and remembers "text\ninformative text" of each. Works for boxes opened with open()
/// and for modal exec() ones (its timer runs inside their event loop).

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

} // namespace trimlab::test
