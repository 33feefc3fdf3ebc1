#include "core/trim/dynamic_rule.h"

namespace trimlab {

bool dynamicInterior(DynamicRule rule, int wReference, int wCurrent, bool interiorInReference)
{
    // "A point belongs to the newly created volume if and only if its index has been
    // modified" (constructive rule, thesis 8.1.1).
    const bool changed = wReference != wCurrent;
    switch (rule) {
    case DynamicRule::ConstructiveAdditive:
        return interiorInReference || changed;
    case DynamicRule::ConstructiveSubtractive:
        return interiorInReference && !changed;
    case DynamicRule::ConstructiveIntersection:
        return interiorInReference && changed;
    case DynamicRule::Confluent:
    case DynamicRule::HomogeneousConfluent:
        // The second, equivalent form of the confluent rule: the sign of the change says
        // whether the interior or the exterior was extended.
        return changed ? wCurrent > wReference : interiorInReference;
    }
    return false;
}

std::string_view dynamicRuleName(DynamicRule rule)
{
    switch (rule) {
    case DynamicRule::ConstructiveAdditive:
        return "additive";
    case DynamicRule::ConstructiveSubtractive:
        return "subtractive";
    case DynamicRule::ConstructiveIntersection:
        return "intersection";
    case DynamicRule::Confluent:
        return "confluent";
    case DynamicRule::HomogeneousConfluent:
        return "homogeneous-confluent";
    }
    return "?";
}

std::optional<DynamicRule> parseDynamicRule(std::string_view name)
{
    for (DynamicRule rule :
         {DynamicRule::ConstructiveAdditive, DynamicRule::ConstructiveSubtractive,
          DynamicRule::ConstructiveIntersection, DynamicRule::Confluent, DynamicRule::HomogeneousConfluent}) {
        if (name == dynamicRuleName(rule))
            return rule;
    }
    return std::nullopt;
}

std::string_view dynamicRuleDisplayName(DynamicRule rule)
{
    switch (rule) {
    case DynamicRule::ConstructiveAdditive:
        return "Constructive (additive)";
    case DynamicRule::ConstructiveSubtractive:
        return "Constructive (subtractive)";
    case DynamicRule::ConstructiveIntersection:
        return "Constructive (intersection)";
    case DynamicRule::Confluent:
        return "Confluent";
    case DynamicRule::HomogeneousConfluent:
        return "Homogeneous confluent";
    }
    return "?";
}

} // namespace trimlab
