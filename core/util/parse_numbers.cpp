#include "core/util/parse_numbers.h"

#include <charconv>
#include <cmath>

namespace trimlab {

std::optional<std::vector<double>> parseNumberList(std::string_view text, int count, std::string* error)
{
    auto fail = [&](std::string why) -> std::optional<std::vector<double>> {
        if (error)
            *error = std::move(why);
        return std::nullopt;
    };
    std::vector<double> values;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        const std::size_t comma = std::min(text.find(',', pos), text.size());
        const std::string_view item = text.substr(pos, comma - pos);
        double v = 0.0;
        const auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), v);
        if (item.empty() || ec != std::errc() || end != item.data() + item.size() || !std::isfinite(v))
            return fail("'" + std::string(item) + "' is not a finite number in '" + std::string(text) + "'");
        values.push_back(v);
        pos = comma + 1;
    }
    if (static_cast<int>(values.size()) != count)
        return fail("expected " + std::to_string(count) + " comma-separated numbers, got " +
                    std::to_string(values.size()) + " in '" + std::string(text) + "'");
    return values;
}

} // namespace trimlab
