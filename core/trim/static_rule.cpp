#include "core/trim/static_rule.h"

namespace trimlab {

namespace {

// Mathematical modulo: the result is in [0, m) also for negative w.
int positiveModulo(int w, int m)
{
    const int r = w % m;
    return r < 0 ? r + m : r;
}

} // namespace

bool isInterior(StaticRule rule, int w)
{
    switch (rule) {
    case StaticRule::Parity:
        return positiveModulo(w, 2) == 1;
    case StaticRule::PositiveIndex:
        return w >= 1;
    case StaticRule::AlternatingBorder: {
        // ceil(w/2) mod 2 == 1  <=>  w mod 4 in {1, 2}  (proof of Theorem 8.1)
        const int r = positiveModulo(w, 4);
        return r == 1 || r == 2;
    }
    }
    return false;
}

std::string_view ruleName(StaticRule rule)
{
    switch (rule) {
    case StaticRule::Parity:
        return "parity";
    case StaticRule::PositiveIndex:
        return "positive-index";
    case StaticRule::AlternatingBorder:
        return "alternating-border";
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
    return std::nullopt;
}

} // namespace trimlab
