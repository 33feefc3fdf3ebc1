#pragma once
/// \file
/// Where a NURBS tessellation samples one parameter direction (nurbs_tessellation.h).

#include <vector>

namespace trimlab {

/// Increasing sample parameters over [knots.front(), knots.back()], both ends included:
/// every distinct knot is a sample, and each non-empty knot span [a, b] is split into
/// max(m, round(segments · (b − a) / domainLength)) equal intervals, where m = 1 for an
/// open direction and m = ceil(3 / #spans) for a closed one (a closed direction needs at
/// least 3 intervals to close without degenerate triangles). `knots` must be a valid
/// clamped knot vector and segments >= 1 (not re-checked).
[[nodiscard]] std::vector<double> tessellationParameters(const std::vector<double>& knots, int segments, bool closed);

} // namespace trimlab
