#include "ui/window/recent_files.h"

#include "core/catalog/scene_source.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>

namespace trimlab::ui {

namespace {

QString normalised(const QString& path)
{
    return QDir::cleanPath(QFileInfo(path).absoluteFilePath());
}

bool listable(const QString& path)
{
    return !path.isEmpty() && !isDemoSource(path.toStdString());
}

} // namespace

void RecentFiles::load(const QSettings& settings)
{
    const QStringList stored = settings.value(m_key).toStringList();
    m_paths.clear();
    // Oldest first, so that the newest ends up in front.
    for (auto it = stored.crbegin(); it != stored.crend(); ++it)
        add(*it);
}

void RecentFiles::save(QSettings& settings) const
{
    settings.setValue(m_key, m_paths);
}

void RecentFiles::add(const QString& path)
{
    if (!listable(path))
        return;
    const QString entry = normalised(path);
    m_paths.removeAll(entry);
    m_paths.prepend(entry);
    while (m_paths.size() > kMaxEntries)
        m_paths.removeLast();
}

void RecentFiles::remove(const QString& path)
{
    if (listable(path))
        m_paths.removeAll(normalised(path));
}

} // namespace trimlab::ui
