#pragma once
/// \file
/// The loop budget of a resolve's fallback for long fragment lists (the S-buffer's
/// in-place sort, AB_LL's list sort; shaders/common/resolve_budget.glsl). Mesa's llvmpipe
/// silently ends every loop of a shader invocation once it has run 65535 loop iterations
/// in total, so a very long list (thousands of fragments) would stay half sorted and its
/// pixel would be silently wrong; with the budget the fallback stops in time and the
/// pixel is reported unresolved. Other drivers have no such limit.

#include "render/gl/gl_functions.h"

namespace trimlab::render {

struct GlCapabilities;

/// Loop iterations a resolve invocation's fallback may spend: 50000 on llvmpipe (the rest
/// of its 65535 is left to the other loops of the same SIMD vector), else INT_MAX.
[[nodiscard]] int resolveLoopBudget(const GlCapabilities& capabilities);

/// Sets `u_loopBudget` of `program` (which must be in use).
void setResolveLoopBudget(GlFunctions& gl, GLuint program, const GlCapabilities& capabilities);

} // namespace trimlab::render
