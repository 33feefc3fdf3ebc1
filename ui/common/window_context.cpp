#include "ui/common/window_context.h"

#include "ui/common/last_directory.h"
#include "ui/common/panel_wheel_guard.h"

#include "core/util/printable_text.h"

#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMainWindow>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>

namespace trimlab::ui {

namespace {

// No control or escape sequence from a file reaches a label as is (printable_text.h).
QString printable(const QString& text)
{
    const QByteArray utf8 = text.toUtf8();
    const std::string shown = printableText(std::string_view(utf8.constData(), std::size_t(utf8.size())));
    return QString::fromUtf8(shown.data(), qsizetype(shown.size()));
}

} // namespace

void WindowContext::showStatus(const QString& text, int timeoutMs) const
{
    const QString message = printable(text);
    m_window.statusBar()->showMessage(message, timeoutMs);
    // A long message is cut at the frame numbers on the right: hovering shows all of it,
    // and View ▸ Messages keeps it.
    m_window.statusBar()->setToolTip(message);
    m_log.add(MessageLog::Kind::Status, message);
}

void WindowContext::showMessage(QMessageBox::Icon icon, const QString& title, const QString& text,
                                const QString& details) const
{
    // Plain text: a file name or a message quoting a file is never read as HTML.
    const QString message = printable(text);
    const QString info = printable(details);
    auto* box = new QMessageBox(icon, title, message, QMessageBox::Ok, &m_window);
    box->setTextFormat(Qt::PlainText);
    box->setInformativeText(info);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
    const MessageLog::Kind kind = icon == QMessageBox::Critical  ? MessageLog::Kind::Error
                                  : icon == QMessageBox::Warning ? MessageLog::Kind::Warning
                                                                 : MessageLog::Kind::Information;
    m_log.add(kind, info.isEmpty() ? message : message + QLatin1Char('\n') + info);
}

QDockWidget* WindowContext::addSideDock(const QString& title, const QString& objectName, QWidget* content,
                                        QDockWidget* tabWith) const
{
    auto* scroll = new QScrollArea;
    scroll->setWidget(content);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    guardPanelWheel(*scroll); // the wheel scrolls the panel, not the control under the cursor
    auto* dock = new QDockWidget(title, &m_window);
    dock->setObjectName(objectName);
    dock->setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea);
    dock->setWidget(scroll);
    m_window.addDockWidget(Qt::RightDockWidgetArea, dock);
    if (tabWith) {
        m_window.tabifyDockWidget(tabWith, dock);
        tabWith->raise();
    }
    return dock;
}

QDockWidget* WindowContext::addBottomDock(const QString& title, const QString& objectName, QWidget* content) const
{
    auto* dock = new QDockWidget(title, &m_window);
    dock->setObjectName(objectName);
    dock->setAllowedAreas(Qt::BottomDockWidgetArea | Qt::TopDockWidgetArea);
    dock->setWidget(content);
    m_window.addDockWidget(Qt::BottomDockWidgetArea, dock);
    return dock;
}

QString WindowContext::sceneBaseName(const QString& fallback) const
{
    const std::shared_ptr<const LoadedScene> scene = m_host.shownScene();
    return scene ? QFileInfo(QString::fromStdString(scene->displayName)).completeBaseName() : fallback;
}

QString WindowContext::lastDirectory() const
{
    return loadLastDirectory(m_settings);
}

QString WindowContext::saveDirectory() const
{
    return loadSaveDirectory(m_settings);
}

void WindowContext::rememberDirectory(const QString& directory) const
{
    saveLastDirectory(m_settings, directory);
}

QString WindowContext::askSavePath(const QString& title, const QStringList& filters, const QString& suggestedName) const
{
    QString filter = filters.front();
    QString path = QFileDialog::getSaveFileName(&m_window, title, saveDirectory() + QLatin1Char('/') + suggestedName,
                                                filters.join(QStringLiteral(";;")), &filter);
    if (path.isEmpty())
        return {};
    const QRegularExpression suffix(QStringLiteral("\\*(\\.\\w+)"));
    bool known = false;
    for (const QString& f : filters)
        known = known || path.endsWith(suffix.match(f).captured(1), Qt::CaseInsensitive);
    if (!known)
        path += suffix.match(filter).captured(1);
    rememberDirectory(QFileInfo(path).absolutePath());
    return path;
}

} // namespace trimlab::ui
