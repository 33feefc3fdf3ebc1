#include "core/trim/static_rule.h"

#include <charconv>
#include <cstdlib>

namespace trimlab {

namespace {

// Mathematical modulo: the result is in [0, m) also for negative w.
int positiveModulo(int w, int m)
{
    const int r = w % m;
    return r < 0 ? r + m : r;
}

// K of "PREFIXK" when `name` starts with `prefix` and the rest is a decimal integer in
// [1, kMaxThreshold].
std::optional<int> thresholdAfter(std::string_view name, std::string_view prefix)
{
    if (!name.starts_with(prefix))
        return std::nullopt;
    const std::string_view digits = name.substr(prefix.size());
    int k = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), k);
    if (error != std::errc() || end != digits.data() + digits.size() || k < 1 || k > StaticRule::kMaxThreshold)
        return std::nullopt;
    return k;
}

} // namespace

bool StaticRule::orientationInvariant() const
{
    switch (m_kind) {
    case Kind::Parity:
    case Kind::Nonzero:
    case Kind::AbsAtLeast:
        return true;
    case Kind::PositiveIndex:
    case Kind::AlternatingBorder:
    case Kind::Negative:
    case Kind::AtLeast:
        return false;
    }
    return false;
}

bool isInterior(StaticRule rule, int w)
{
    switch (rule.kind()) {
    case StaticRule::Kind::Parity:
        return positiveModulo(w, 2) == 1;
    case StaticRule::Kind::PositiveIndex:
        return w >= 1;
    case StaticRule::Kind::AlternatingBorder: {
        // ceil(w/2) mod 2 == 1  <=>  w mod 4 in {1, 2}  (proof of Theorem 8.1)
        const int r = positiveModulo(w, 4);
        return r == 1 || r == 2;
    }
    case StaticRule::Kind::Nonzero:
        return w != 0;
    case StaticRule::Kind::Negative:
        return w < 0;
    case StaticRule::Kind::AtLeast:
        return w >= rule.threshold();
    case StaticRule::Kind::AbsAtLeast:
        return std::abs(w) >= rule.threshold();
    }
    return false;
}

std::string ruleName(StaticRule rule)
{
    switch (rule.kind()) {
    case StaticRule::Kind::Parity:
        return "parity";
    case StaticRule::Kind::PositiveIndex:
        return "positive-index";
    case StaticRule::Kind::AlternatingBorder:
        return "alternating-border";
    case StaticRule::Kind::Nonzero:
        return "nonzero";
    case StaticRule::Kind::Negative:
        return "negative";
    case StaticRule::Kind::AtLeast:
        return "w>=" + std::to_string(rule.threshold());
    case StaticRule::Kind::AbsAtLeast:
        return "|w|>=" + std::to_string(rule.threshold());
    }
    return "?";
}

std::optional<StaticRule> parseStaticRule(std::string_view name)
{
    if (name == "parity")
        return StaticRule::Parity;
    if (name == "positive-index" || name == "positive")
        return StaticRule::PositiveIndex;
    if (name == "alternating-border" || name == "alternating")
        return StaticRule::AlternatingBorder;
    if (name == "nonzero")
        return StaticRule::Nonzero;
    if (name == "negative")
        return StaticRule::Negative;
    for (std::string_view prefix : {"w>=", "at-least-"})
        if (const std::optional<int> k = thresholdAfter(name, prefix))
            return StaticRule::atLeast(*k);
    for (std::string_view prefix : {"|w|>=", "abs-at-least-"})
        if (const std::optional<int> k = thresholdAfter(name, prefix))
            return StaticRule::absAtLeast(*k);
    return std::nullopt;
}

std::string staticRuleNamesHelp()
{
    return "parity, positive-index, alternating-border, nonzero, negative, w>=K or |w|>=K (also at-least-K, "
           "abs-at-least-K; K from 1 to " +
           std::to_string(StaticRule::kMaxThreshold) + ")";
}

int shaderRuleCode(StaticRule rule)
{
    return int(rule.kind()) | (rule.threshold() << 4);
}

} // namespace trimlab
