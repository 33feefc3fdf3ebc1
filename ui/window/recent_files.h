#pragma once
/// \file
/// The list behind File ▸ Open Recent: the most recently opened mesh files, newest first,
/// as absolute clean paths, without duplicates, at most kMaxEntries. Demo scenes are not
/// files and are never listed. The same class keeps File ▸ Open Recent Animation under
/// another settings key (animations are folders and patterns as well as files).

#include <QString>
#include <QStringList>

#include <utility>

class QSettings;

namespace trimlab::ui {

class RecentFiles {
public:
    static constexpr int kMaxEntries = 10;

    /// `settingsKey`: where load() and save() keep the list.
    explicit RecentFiles(QString settingsKey = QStringLiteral("recentFiles")) : m_key(std::move(settingsKey)) {}

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
    QString m_key;
    QStringList m_paths;
};

} // namespace trimlab::ui
