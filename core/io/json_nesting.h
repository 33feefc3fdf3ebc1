#pragma once
/// \file
/// A guard for JSON readers: tinygltf and nlohmann::json recurse once per nesting level,
/// so an absurdly nested document would overflow the stack before they could report it.

#include <cstddef>
#include <string_view>

namespace trimlab::io {

/// Offset of the first '[' or '{' nested deeper than `maxDepth` in `json` (brackets in
/// strings are skipped), or std::string_view::npos when none is.
[[nodiscard]] std::size_t jsonTooDeepAt(std::string_view json, std::size_t maxDepth);

} // namespace trimlab::io
