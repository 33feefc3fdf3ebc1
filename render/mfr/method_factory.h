#pragma once
/// \file
/// Creates the multi-fragment method of a kind.

#include "render/mfr/fragment_method.h"

#include <memory>

namespace trimlab::render {

/// A new method object (GL resources are allocated on its first frame). Throws
/// std::invalid_argument for a kind without an implementation.
[[nodiscard]] std::unique_ptr<FragmentMethod> createFragmentMethod(FragmentMethodKind kind, GlFunctions& gl);

} // namespace trimlab::render
