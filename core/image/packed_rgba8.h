#pragma once
/// \file
/// Colours packed for the GPU: one RGBA8 value per vertex, as GLSL's unpackUnorm4x8
/// reads it (red in the lowest byte). The viewport's vertex colours (segments, heat
/// maps, skeleton stages, the brush region) all go through packRgba8.

#include <glm/vec3.hpp>

#include <cstdint>

namespace trimlab {

/// One RGBA8 value from RGB in [0, 1] (clamped, rounded), alpha 255.
[[nodiscard]] std::uint32_t packRgba8(const glm::vec3& rgb);

} // namespace trimlab
