#pragma once
/// \file
/// Dynamic interior/exterior classification rules of thesis 8.1.1 ("Dynamic Rules",
/// Table 8.1). A dynamic rule classifies a point p after a set of concurrent disjoint
/// deformations from three values: its winding index in the set's reference frame
/// w(p,S), its index in the current frame w(p,S') and its classification in the reference
/// frame i(p,S). Within one set a point of space is crossed at most once, so the two
/// indices differ by at most one there; the functions accept any values.

#include <optional>
#include <string_view>

namespace trimlab {

enum class DynamicRule {
    ConstructiveAdditive,     ///< i(p,S') = i(p,S) OR  changed   (union with the swept volume)
    ConstructiveSubtractive,  ///< i(p,S') = i(p,S) AND NOT changed (difference)
    ConstructiveIntersection, ///< i(p,S') = i(p,S) AND changed   (intersection)
    Confluent,                ///< unchanged: i(p,S); index grew: in; index shrank: out
    HomogeneousConfluent,     ///< Confluent, and trimmed-off parts may not be deformed
};

/// i(p,S') for `rule` (true = interior). changed means wReference != wCurrent.
[[nodiscard]] bool dynamicInterior(DynamicRule rule, int wReference, int wCurrent, bool interiorInReference);

/// Stable names for files and the command line: "additive", "subtractive", "intersection",
/// "confluent", "homogeneous-confluent".
[[nodiscard]] std::string_view dynamicRuleName(DynamicRule rule);
/// Inverse of dynamicRuleName; nullopt if unknown.
[[nodiscard]] std::optional<DynamicRule> parseDynamicRule(std::string_view name);
/// Menu text, e.g. "Constructive (additive)".
[[nodiscard]] std::string_view dynamicRuleDisplayName(DynamicRule rule);

/// Whether the rule forbids deforming trimmed-off parts of the surface.
[[nodiscard]] inline bool forbidsDeformingTrimmedParts(DynamicRule rule)
{
    return rule == DynamicRule::HomogeneousConfluent;
}

} // namespace trimlab
