#pragma once
/// \file
/// Strict parsing of comma-separated numbers for command-line options.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace trimlab {

/// Parses exactly `count` finite, comma-separated numbers ("1,2.5,-3e2"). On failure
/// returns nullopt and writes a one-line reason to `error` (if given).
[[nodiscard]] std::optional<std::vector<double>> parseNumberList(std::string_view text, int count, std::string* error);

} // namespace trimlab
