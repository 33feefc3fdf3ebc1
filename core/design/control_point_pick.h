#pragma once
/// \file
/// Which control point a click means, and how a click changes the selection (the
/// control-point tool's rules, kept apart from the widget so they read as a table):
/// - a plain click on a point selects it alone; on empty space it clears the selection;
/// - Shift + click on a point toggles it in the selection; on empty space it keeps it.
/// Positions are logical widget coordinates (x right, y down).

#include <glm/vec2.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace trimlab {

/// The index of the projected point nearest to `cursor` within `maxDistance` (pixels),
/// or nullopt. Unprojected points (nullopt: behind the eye) are skipped; ties go to the
/// lower index.
[[nodiscard]] std::optional<std::uint32_t>
nearestPoint(glm::dvec2 cursor, std::span<const std::optional<glm::dvec2>> points, double maxDistance);

/// The selection after a click on `picked` (nullopt: empty space) with `toggle` (Shift)
/// held. `selection` and the result are ascending and unique.
[[nodiscard]] std::vector<std::uint32_t> clickedSelection(std::vector<std::uint32_t> selection,
                                                          std::optional<std::uint32_t> picked, bool toggle);

} // namespace trimlab
