#pragma once
/// \file
/// A submenu of recent files (File ▸ Open Recent, Open Recent Animation): the entries of
/// a RecentFiles list kept in the settings, newest first, then Clear List — or "(none)".
/// Choosing an entry calls the opener with its path; the list is saved after each change.

#include "ui/window/recent_files.h"

#include <QObject>
#include <QString>

#include <functional>

class QMenu;
class QSettings;

namespace trimlab::ui {

class RecentFilesMenu : public QObject {
    Q_OBJECT
public:
    using Opener = std::function<void(const QString& path)>;

    /// Fills `menu` (owned by the caller) from the list stored under `settingsKey`.
    RecentFilesMenu(QMenu* menu, QSettings& settings, const QString& settingsKey, Opener open,
                    QObject* parent = nullptr);

    [[nodiscard]] const QStringList& paths() const { return m_recent.paths(); }
    /// Puts `path` first (RecentFiles::add); saved and shown.
    void add(const QString& path);
    /// Drops `path`, e.g. a file that no longer exists; saved and shown.
    void remove(const QString& path);

private:
    void rebuild();
    void clear();

    QMenu* m_menu;
    QSettings& m_settings;
    RecentFiles m_recent;
    Opener m_open;
};

} // namespace trimlab::ui
