#pragma once
/// \file
/// The editable-surface parts of a project file (format version 2, docs/project-format.md):
/// the surface definition a history's base mesh was tessellated from, and the control
/// moves of control-point edit frames. Exact: NURBS numbers are written with round-trip
/// precision (nurbs_json.h), cage positions and control moves as float64 binary arrays
/// (binary_array.h). Internal to core/timeline (project_file.cpp); errors are
/// JsonPathError naming the JSON path.

#include "core/surface/surface_definition.h"
#include "core/timeline/timeline.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace trimlab::timeline {

/// {"kind": "nurbs", "nurbs": <a trimlab-nurbs document with one surface>,
///  "segments_u": N, "segments_v": N} or {"kind": "subdivision", "scheme": ..., ...}.
/// Throws std::invalid_argument for an invalid definition.
[[nodiscard]] nlohmann::json surfaceDefinitionJson(const SurfaceDefinition& definition);
/// Reads and validates (findSurfaceDefinitionProblem) a definition; JsonPathError with the
/// path of the offending value ("surface.nurbs.surfaces[0].weights[3]", "surface.level").
[[nodiscard]] SurfaceDefinition readSurfaceDefinition(const nlohmann::json& value, const std::string& path);

/// {"indices": uint32 array, "before": float64 array (#×3), "after": float64 array (#×3)}.
[[nodiscard]] nlohmann::json controlMovesJson(const std::vector<ControlPointMove>& moves);
/// Reads control moves: the three arrays must agree in length and list at least one
/// move. Order, range and 'before' consistency are Timeline's checks.
[[nodiscard]] std::vector<ControlPointMove> readControlMoves(const nlohmann::json& value, const std::string& path);

} // namespace trimlab::timeline
