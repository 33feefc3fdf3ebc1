#pragma once
/// \file
/// Reading and writing the render choices in a QSettings (keys "render/…"; the file
/// dialogs' last directory: ui/common/last_directory.h; recent files: recent_files.h;
/// clipping plane 1 keeps the keys of the one plane of earlier versions, planes 2–6 are
/// "render/clipPlaneN/…"; capping and highlighting "render/cap…", "render/highlight…";
/// X-ray "render/xrayMode" ("off", "opaque", "translucent"); the keys and ranges of k, S,
/// the memory budget, the X-ray numbers and the cap spacing are the rows of
/// render/mfr/method_parameter_table.h and core/trim/inspect_parameters.h;
/// the CSG expression and per-object rules belong to the scene and are not stored;
/// window geometry and dock state: main_window.cpp). The method is stored by its stable
/// id ("render/method"), the classification as "static" or "dynamic"
/// ("render/classification"). Values that are missing or unusable (unknown rule name, a method
/// this build lacks, k or S out of range, zero or non-finite normal, unknown cap pattern,
/// cap spacing out of range, unknown X-ray mode, X-ray values out of range) fall back to
/// firstStartRenderChoices(), field by field — so no saved settings means first start.

#include "ui/render_panel/render_choices.h"

class QSettings;

namespace trimlab::ui {

[[nodiscard]] RenderChoices loadRenderChoices(const QSettings& settings);
void saveRenderChoices(QSettings& settings, const RenderChoices& choices);

} // namespace trimlab::ui
