#pragma once
/// \file
/// The list behind File ▸ Open Recent: the most recently opened mesh files, newest first,
/// as absolute clean paths, without duplicates, at most kMaxEntries. Demo scenes are not
/// files and are never listed.

#include <QStringList>

class QSettings;

namespace trimlab::ui {

class RecentFiles {
public:
    static constexpr int kMaxEntries = 10;

    /// Replaces the list with the one stored in `settings` (normalised as add() would).
    void load(const QSettings& settings);
    void save(QSettings& settings) const;

    /// Puts `path` first (moving it if listed); drops the oldest beyond kMaxEntries.
    /// Empty paths and "demo:" sources are ignored.
    void add(const QString& path);
    /// Removes `path` (compared after normalisation); no-op when not listed.
    void remove(const QString& path);

    [[nodiscard]] const QStringList& paths() const { return m_paths; }

private:
    QStringList m_paths;
};

} // namespace trimlab::ui
