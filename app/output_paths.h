#pragma once
/// \file
/// The verbs' output paths checked before any work (core/io/output_paths.h), with Qt's
/// strings: exit code 2 and one line when a path cannot be written.

#include <QString>

#include <initializer_list>
#include <optional>
#include <utility>

namespace trimlab::app {

/// checkOutputPaths over (option, path) pairs; empty paths are outputs not requested.
[[nodiscard]] std::optional<QString> checkOutputPaths(std::initializer_list<std::pair<const char*, QString>> outputs);

} // namespace trimlab::app
