#pragma once
/// \file
/// The folder every file dialog of the window starts in (key "paths/lastDirectory"): the
/// one the user last opened or saved a file in, shared by all features.

#include <QString>

class QSettings;

namespace trimlab::ui {

/// The folder file dialogs start in; the user's home folder when none was saved or it
/// no longer exists.
[[nodiscard]] QString loadLastDirectory(const QSettings& settings);
void saveLastDirectory(QSettings& settings, const QString& directory);

} // namespace trimlab::ui
