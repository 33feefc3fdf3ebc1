#pragma once
/// \file
/// "Natural" file name order for mesh sequences: runs of digits compare as numbers, so
/// "mesh_2.obj" comes before "mesh_10.obj".

#include <string_view>

namespace trimlab {

/// Strict weak order on names: the names are split into runs of digits and runs of other
/// characters; digit runs compare by numeric value (any length, no overflow), other runs
/// character by character ignoring ASCII case. Ties are broken by fewer leading zeros
/// first ("7" < "007"), then by plain byte order, so distinct names never compare equal.
[[nodiscard]] bool naturalLess(std::string_view a, std::string_view b);

} // namespace trimlab
