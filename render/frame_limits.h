#pragma once
/// \file
/// What a frame may use before anything is allocated: the driver's texture limits (the
/// render target and every per-pixel image are width×height textures; the k slots are
/// layers of one array texture) and the user's GPU memory budget for the methods whose
/// storage is known in advance (MethodParameters::memoryBudgetBytes; the counted methods'
/// node buffers check it when they grow, mfr/node_buffer.h). A frame beyond them throws
/// GpuMemoryError with what was asked, the limit, and what to change — before any
/// allocation, so the previous frame's storage stays as it was.

#include "render/gl/gl_capabilities.h"
#include "render/mfr/fragment_method.h"

#include <cstddef>
#include <optional>

namespace trimlab::render {

/// Throws GpuMemoryError when width or height exceed the driver's GL_MAX_TEXTURE_SIZE,
/// when k exceeds GL_MAX_ARRAY_TEXTURE_LAYERS (slot methods), or when
/// `estimatedMethodBytes` (nullopt: scene-dependent, not checked here) exceeds a
/// non-zero budget in `parameters`.
void checkFrameLimits(FragmentMethodKind method, const GlCapabilities& capabilities, const MethodParameters& parameters,
                      std::optional<std::size_t> estimatedMethodBytes, int width, int height);

} // namespace trimlab::render
