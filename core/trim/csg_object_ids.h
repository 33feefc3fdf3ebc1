#pragma once
/// \file
/// Whether CSG settings fit a scene: every object id the expression or a per-object rule
/// names must be an object of it. The command line's --csg and --object-rule and the
/// Python module's csg= and rules= refuse the same ids with the same reason, each
/// prefixing its own name for the setting.

#include "core/trim/inspect_settings.h"

#include <cstddef>
#include <optional>
#include <string>

namespace trimlab {

/// The first id outside a scene of `objectCount` objects: the expression's largest id, or
/// else the smallest object rule's id.
struct CsgObjectIdProblem {
    bool inExpression = false; ///< false: in CsgSettings::objectRules
    int id = 0;
};

[[nodiscard]] std::optional<CsgObjectIdProblem> csgObjectIdOutsideScene(const CsgSettings& csg,
                                                                        std::size_t objectCount);

/// The reason a setting naming object `id` is refused: "refers to object 3, but the scene
/// has 2 object(s) (ids 0 to 1)".
[[nodiscard]] std::string csgObjectIdReason(int id, std::size_t objectCount);

} // namespace trimlab
