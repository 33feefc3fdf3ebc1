#pragma once
/// \file
/// Replaying a stroke script on a mesh: the headless counterpart of the designer's brush
/// (`trimlab render --script S.json --frame N`).

#include "core/util/task_control.h"
#include "core/mesh/triangle_mesh.h"
#include "core/timeline/stroke_script.h"
#include "core/timeline/timeline.h"

#include <string>

namespace trimlab::timeline {

/// Applies every stroke of `script` to `base`, in order, and returns the history: the
/// first script set becomes set 0 (its rule replaces the default), every later one a
/// Timeline::startSet. Each frame records the stroke as resolved by deform::BrushStroke
/// (anchor on the surface, anchorTriangle set) and exactly the vertices whose bits
/// changed, with their positions before and after. Replaying the same script on the same
/// mesh gives a bit-identical timeline.
/// Throws StrokeScriptError naming the stroke ("sets[1].strokes[0]: triangle 900 is out
/// of range") when the brush refuses a stroke; OperationCancelled when `control` asks to
/// stop (stage "replay", one item per stroke; reported after every stroke).
/// `sourceName` names the script in errors (its file name, usually).
[[nodiscard]] Timeline replayStrokeScript(const TriangleMesh& base, const StrokeScript& script,
                                          const TaskControl& control = {},
                                          const std::string& sourceName = "stroke script");

} // namespace trimlab::timeline
