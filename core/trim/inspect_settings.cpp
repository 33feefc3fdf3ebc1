#include "trim/inspect_settings.h"

namespace trimlab {

std::string_view capPatternName(CapPattern pattern)
{
    switch (pattern) {
    case CapPattern::Hatched:
        return "hatched";
    case CapPattern::Striped:
        return "striped";
    case CapPattern::Solid:
        return "solid";
    }
    return "?";
}

std::optional<CapPattern> parseCapPattern(std::string_view name)
{
    for (CapPattern pattern : {CapPattern::Hatched, CapPattern::Striped, CapPattern::Solid})
        if (capPatternName(pattern) == name)
            return pattern;
    return std::nullopt;
}

} // namespace trimlab
