#pragma once
/// \file
/// How a shown trim point is colored. The GLSL twin is shaders/common/trim_shading.glsl;
/// keep the two identical (render tests compare colors against the CPU reference).

#include <glm/vec3.hpp>

namespace trimlab {

/// Front-facing surface: warm yellow; back-facing (the inside seen through a cut or a
/// trimmed hole): blue — the convention of the thesis figures (Fig. 8.11).
inline constexpr glm::vec3 kFrontFacingColor{0.96f, 0.78f, 0.26f};
inline constexpr glm::vec3 kBackFacingColor{0.28f, 0.50f, 0.96f};
inline constexpr glm::vec3 kBackgroundColor{0.16f, 0.17f, 0.20f};
inline constexpr float kAmbient = 0.25f;

/// Headlight Lambert shading. `normal`: unit surface normal (any orientation);
/// `toViewer`: unit vector from the point to the eye; `facing`: +1 or −1.
[[nodiscard]] glm::vec3 shadeTrimPoint(int facing, const glm::dvec3& normal, const glm::dvec3& toViewer);

} // namespace trimlab
