#pragma once
/// \file
/// Static interior/exterior classification rules of thesis 8.1.1: pure functions of the
/// winding index w of a point (the index of its component of space).

#include <optional>
#include <string_view>

namespace trimlab {

enum class StaticRule {
    Parity,            ///< in iff w is odd ("alternating interior"); orientation invariant
    PositiveIndex,     ///< in iff w >= 1 (Heisserman's positive index rule)
    AlternatingBorder, ///< in iff ceil(w/2) mod 2 == 1, i.e. w mod 4 in {1, 2}
};

/// Classification of a point with winding index `w` under `rule` (true = interior).
[[nodiscard]] bool isInterior(StaticRule rule, int windingIndex);

/// A surface fragment separating index `wBefore` from `wAfter` belongs to the trim iff the
/// two sides classify differently.
[[nodiscard]] inline bool isTrimBoundary(StaticRule rule, int wBefore, int wAfter)
{
    return isInterior(rule, wBefore) != isInterior(rule, wAfter);
}

/// Stable command-line / settings names: "parity", "positive-index", "alternating-border".
[[nodiscard]] std::string_view ruleName(StaticRule rule);
/// Inverse of ruleName (also accepts "positive" and "alternating"); nullopt if unknown.
[[nodiscard]] std::optional<StaticRule> parseStaticRule(std::string_view name);

} // namespace trimlab
