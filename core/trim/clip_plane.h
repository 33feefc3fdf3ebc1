#pragma once
/// \file
/// A clipping plane and the part of a pixel ray it keeps.

#include "core/view/camera.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace trimlab {

/// Plane n·x + offset = 0 in world space. Points with n·x + offset >= 0 are kept (the
/// OpenGL gl_ClipDistance convention); the rest is clipped away. `normal` need not be
/// unit length. A disabled plane keeps everything.
struct ClipPlane {
    bool enabled = false;
    glm::dvec3 normal{0.0, 0.0, -1.0};
    double offset = 0.0;

    [[nodiscard]] double evaluate(const glm::dvec3& p) const { return glm::dot(normal, p) + offset; }
    [[nodiscard]] glm::dvec4 equation() const { return {normal, offset}; }
    /// The same plane keeping the other side.
    [[nodiscard]] ClipPlane flipped() const { return {enabled, -normal, -offset}; }
    friend bool operator==(const ClipPlane&, const ClipPlane&) = default;
};

/// The interval [tStart, tEnd] (view depths, see PixelRay) of a ray that survives both
/// the camera's near/far planes and the clip plane. Empty when nothing survives.
/// The winding index is evaluated at tStart: at the near plane when the ray starts in
/// the kept half-space, at the clip plane when it enters it there.
struct KeptSpan {
    bool empty = true;
    double tStart = 0.0;
    double tEnd = 0.0;
    /// True when tStart is the near plane (the ray starts inside the kept half-space).
    bool startsAtNear = true;
    /// Which plane of a ClipSet bounds the span at tStart (−1: the near plane) and at
    /// tEnd (−1: the far plane). keptSpan(ClipPlane) reports plane 0.
    int startPlane = -1;
    int endPlane = -1;
    /// The runner-up plane bound at each end (the next largest lower bound of another
    /// plane behind tStart, the next smallest upper bound beyond tEnd), −inf / +inf when
    /// no other plane bounds that end: where two planes nearly tie, which one bounds the
    /// span may flip under rounding (reference_diagnostics.h counts it as a depth margin).
    double startRunnerUp = -std::numeric_limits<double>::infinity();
    double endRunnerUp = std::numeric_limits<double>::infinity();
};

[[nodiscard]] KeptSpan keptSpan(const ClipPlane& plane, const PixelRay& ray, double zNear, double zFar);

/// Parses "a,b,c,d" (the CLI's --clip) into an enabled plane; nullopt and `error` on bad
/// input (including a zero normal).
[[nodiscard]] std::optional<ClipPlane> parseClipPlane(std::string_view text, std::string* error);

} // namespace trimlab
