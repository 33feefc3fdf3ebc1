#pragma once
/// \file
/// One brush stroke as JSON, shared by stroke scripts and project files:
/// `{"anchor": [x,y,z], "triangle": 123, "drag": [dx,dy,dz], "radius": 0.3,
///   "strength": 1.0, "profile": "smooth",
///   "smoothing": {"iterations": 2, "weights": "uniform", "step": 0.5}}`.
/// "anchor" and "drag" are required; every other field defaults to BrushSettings'
/// default. Doubles are written with round-trip precision (nlohmann writes the shortest
/// text that reads back to the same double), so a written stroke reads back bit-exactly.
/// Internal to core/timeline; docs/project-format.md documents the schema.

#include "core/deform/stroke.h"

#include <nlohmann/json.hpp>

#include <string>

namespace trimlab::timeline {

/// Every field, defaults included ("triangle" only when the stroke has one). Throws
/// std::invalid_argument for a stroke strokeProblem() refuses (it could not be read back).
[[nodiscard]] nlohmann::json strokeJson(const deform::Stroke& stroke);

/// Reads a stroke object at `path`. Throws JsonPathError naming the field and the reason:
/// a missing anchor/drag, a wrong type, unknown names ("profile: unknown profile 'soft'
/// (known: smooth, linear, sharp)"), radius <= 0, step outside (0, 1], iterations < 0,
/// and — when `rejectUnknown` — fields the schema does not define.
[[nodiscard]] deform::Stroke readStrokeJson(const nlohmann::json& value, const std::string& path, bool rejectUnknown);

} // namespace trimlab::timeline
