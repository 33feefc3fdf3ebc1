#pragma once
/// \file
/// What every feature workspace of the main window shares (docs/architecture.md): the
/// window whose docks, menus, tool bars and status bar it adds to and whose dialogs it
/// parents, the settings it keeps its choices in, the scene host (scene_host.h) and the
/// document shown (current_document.h: its file, view settings, undo stack, modified
/// state) — with the few things all features do with them: show a status message or a
/// message box, add a dock, ask for a file in the last folder used.
///
/// MainWindow owns one and hands it to each workspace it composes; a workspace keeps the
/// reference (the window outlives its workspaces).

#include "ui/common/current_document.h"
#include "ui/common/message_log.h"
#include "ui/common/scene_host.h"

#include <QMessageBox>
#include <QString>
#include <QStringList>

class QDockWidget;
class QMainWindow;
class QSettings;
class QWidget;

namespace trimlab::ui {

/// How long a status bar message stays (milliseconds).
inline constexpr int kStatusMessageMs = 5000;

class WindowContext {
public:
    WindowContext(QMainWindow& window, QSettings& settings, SceneHost& host, CurrentDocument& document, MessageLog& log)
        : m_window(window), m_settings(settings), m_host(host), m_document(document), m_log(log)
    {
    }

    [[nodiscard]] QMainWindow& window() const { return m_window; }
    [[nodiscard]] QSettings& settings() const { return m_settings; }
    [[nodiscard]] SceneHost& host() const { return m_host; }
    /// The document shown (its file, view settings, undo stack and modified state).
    [[nodiscard]] CurrentDocument& document() const { return m_document; }
    /// The shown scene's display name without its extension (`fallback` without a scene):
    /// what export dialogs suggest as a file name, followed by their own ending.
    [[nodiscard]] QString sceneBaseName(const QString& fallback) const;

    /// Both record the message in log() too.
    void showStatus(const QString& message, int timeoutMs = kStatusMessageMs) const;
    /// Window-modal and non-blocking: loading and rendering continue behind it.
    void showMessage(QMessageBox::Icon icon, const QString& title, const QString& text, const QString& details) const;
    /// Every message shown so far (ui/common/message_log.h).
    [[nodiscard]] MessageLog& log() const { return m_log; }

    /// A dock on the right (or left) side titled `title` holding `content` in a frameless
    /// scroll area; `objectName` names it in the saved window state. With `tabWith` it is
    /// tabbed behind that dock, which stays in front.
    QDockWidget* addSideDock(const QString& title, const QString& objectName, QWidget* content,
                             QDockWidget* tabWith = nullptr) const;
    /// A dock at the bottom (or top) holding `content` as it is.
    QDockWidget* addBottomDock(const QString& title, const QString& objectName, QWidget* content) const;

    /// The folder file dialogs start in (ui/common/last_directory.h).
    [[nodiscard]] QString lastDirectory() const;
    /// The folder save dialogs start in (a writable one: loadSaveDirectory()).
    [[nodiscard]] QString saveDirectory() const;
    void rememberDirectory(const QString& directory) const;
    /// Asks for a file to write, starting in saveDirectory() at `suggestedName`; `filters`
    /// are dialog filters with one suffix each ("glTF (*.gltf)"). A name that ends in none
    /// of the filters' suffixes gets the chosen filter's. Remembers the folder; "" when the
    /// user cancels.
    [[nodiscard]] QString askSavePath(const QString& title, const QStringList& filters,
                                      const QString& suggestedName) const;

private:
    QMainWindow& m_window;
    QSettings& m_settings;
    SceneHost& m_host;
    CurrentDocument& m_document;
    MessageLog& m_log;
};

} // namespace trimlab::ui
