#include "ui/window/recent_files_menu.h"

#include <QMenu>
#include <QSettings>

namespace trimlab::ui {

RecentFilesMenu::RecentFilesMenu(QMenu* menu, QSettings& settings, const QString& settingsKey, Opener open,
                                 QObject* parent)
    : QObject(parent), m_menu(menu), m_settings(settings), m_recent(settingsKey), m_open(std::move(open))
{
    m_recent.load(m_settings);
    rebuild();
}

void RecentFilesMenu::add(const QString& path)
{
    m_recent.add(path);
    m_recent.save(m_settings);
    rebuild();
}

void RecentFilesMenu::remove(const QString& path)
{
    m_recent.remove(path);
    m_recent.save(m_settings);
    rebuild();
}

void RecentFilesMenu::clear()
{
    const QStringList paths = m_recent.paths(); // a copy: removing changes the list
    for (const QString& path : paths)
        m_recent.remove(path);
    m_recent.save(m_settings);
    rebuild();
}

void RecentFilesMenu::rebuild()
{
    m_menu->clear();
    for (const QString& path : m_recent.paths())
        m_menu->addAction(path, this, [this, path] { m_open(path); });
    if (m_recent.paths().isEmpty()) {
        m_menu->addAction(tr("(none)"))->setEnabled(false);
        return;
    }
    m_menu->addSeparator();
    m_menu->addAction(tr("Clear List"), this, &RecentFilesMenu::clear);
}

} // namespace trimlab::ui
