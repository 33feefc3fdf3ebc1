#pragma once
/// \file
/// The folder every file dialog of the window starts in (key "paths/lastDirectory"): the
/// one the user last opened or saved a file in, shared by all features.

#include <QString>

#include <functional>

class QSettings;

namespace trimlab::ui {

/// The folder file dialogs start in; the user's home folder when none was saved or it
/// no longer exists.
[[nodiscard]] QString loadLastDirectory(const QSettings& settings);
void saveLastDirectory(QSettings& settings, const QString& directory);
/// The folder save dialogs start in: the last directory when it is writable, else the
/// user's Pictures folder, else the home folder. Files are often opened from read-only
/// folders (shared data, a mounted archive), where Export Image used to start.
[[nodiscard]] QString loadSaveDirectory(const QSettings& settings);
/// The same with `writable` deciding which folders can be written (tests stand in for a
/// read-only mount, which permissions cannot make for the root user).
[[nodiscard]] QString loadSaveDirectory(const QSettings& settings, const std::function<bool(const QString&)>& writable);

} // namespace trimlab::ui
