#pragma once
/// \file
/// The pinhole camera shared by the GPU renderer and the CPU reference. Both derive every
/// pixel's ray from the same numbers, so their images can be compared pixel by pixel.

#include "core/mesh/triangle_mesh.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <string_view>

namespace trimlab {

/// Perspective camera. `zNear`/`zFar` are view-space depths (> 0). The far plane must lie
/// beyond the scene: the winding index is counted from the far side (see trim/), and a
/// fragment cut by the far plane would be lost from that count. Use `withDepthRange`.
struct Camera {
    glm::dvec3 eye{0.0, 0.0, 3.0};
    glm::dvec3 target{0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fovyDegrees = 45.0;
    double zNear = 0.01;
    double zFar = 100.0;

    friend bool operator==(const Camera&, const Camera&) = default;
};

/// World → view (right-handed, camera looks down −z).
[[nodiscard]] glm::dmat4 viewMatrix(const Camera& camera);
/// View → clip, OpenGL conventions (NDC z in [−1, 1]).
[[nodiscard]] glm::dmat4 projectionMatrix(const Camera& camera, double aspect);

/// A pixel's primary ray. `direction` is scaled so that its view-space z is −1: the ray
/// parameter t of a point equals its view depth, the quantity the GPU stores per fragment.
struct PixelRay {
    glm::dvec3 origin;
    glm::dvec3 direction;
};

/// Ray through the centre of pixel (x, y) of a width×height image; row 0 is the top row.
[[nodiscard]] PixelRay pixelRay(const Camera& camera, int width, int height, int x, int y);

/// Returns `camera` with zNear/zFar chosen to enclose `bounds` with margin, keeping the
/// near plane small enough for the camera to sit inside the scene.
[[nodiscard]] Camera withDepthRange(Camera camera, const Bounds& bounds);

/// A camera looking at `bounds` from `viewDirection` (pointing from the eye to the
/// target) so the bounding sphere fills the view at the given aspect; depth range set.
[[nodiscard]] Camera fitCamera(const Bounds& bounds, double aspect,
                               const glm::dvec3& viewDirection = glm::dvec3(-0.35, -0.45, -1.0));

/// Parses "ex,ey,ez,tx,ty,tz,ux,uy,uz,fovy" (the CLI's --camera). Returns an error text
/// in `error` and nullopt on bad input. zNear/zFar are left for withDepthRange.
[[nodiscard]] std::optional<Camera> parseCamera(std::string_view text, std::string* error);
[[nodiscard]] std::string formatCamera(const Camera& camera);

} // namespace trimlab
