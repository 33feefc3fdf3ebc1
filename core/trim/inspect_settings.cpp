#include "core/trim/inspect_settings.h"

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

std::string_view trimDisplayName(TrimDisplay display)
{
    return display == TrimDisplay::Opaque ? "opaque" : "translucent";
}

std::optional<TrimDisplay> parseTrimDisplay(std::string_view name)
{
    for (TrimDisplay display : {TrimDisplay::Opaque, TrimDisplay::Translucent})
        if (trimDisplayName(display) == name)
            return display;
    return std::nullopt;
}

} // namespace trimlab
