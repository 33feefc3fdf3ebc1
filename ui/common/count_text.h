#pragma once
/// \file
/// "1 vertex", "42 vertices": a count with its noun in the right number. Qt's %n picks
/// the plural only through a loaded translation, so without one it printed "1 vertices".

#include <QString>

namespace trimlab::ui {

/// `count` (grouped by the locale) and `one` when count is 1, else `many`.
[[nodiscard]] QString countOf(long long count, const QString& one, const QString& many);

} // namespace trimlab::ui
