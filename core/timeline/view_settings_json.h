#pragma once
/// \file
/// The "view_settings" object of a project file (docs/project-format.md): a document's
/// StoredViewSettings as JSON. Every field is written; on reading, a missing field keeps
/// its default (files are only ever extended) and a mistyped or out-of-range one is
/// refused with its JSON path, as every other project field is.

#include "core/timeline/view_settings.h"

#include <nlohmann/json.hpp>

#include <string>

namespace trimlab::timeline {

[[nodiscard]] nlohmann::json viewSettingsJson(const StoredViewSettings& settings);
/// Throws JsonPathError naming the field below `path`.
[[nodiscard]] StoredViewSettings readViewSettings(const nlohmann::json& value, const std::string& path);

} // namespace trimlab::timeline
