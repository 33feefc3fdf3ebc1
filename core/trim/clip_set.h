#pragma once
/// \file
/// Several clipping planes at once (up to six, e.g. a clipping box) and the part of a
/// pixel ray they keep together. Each plane keeps its half-space n·x + offset >= 0
/// (ClipPlane); the set keeps the intersection of the enabled half-spaces with the
/// camera's [zNear, zFar], which is convex, so every ray keeps one interval (KeptSpan).
/// The GLSL twin is shaders/common/clip.glsl.

#include "core/trim/clip_plane.h"
#include "core/view/camera.h"

#include <glm/vec3.hpp>

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace trimlab {

/// The most clipping planes a ClipSet holds (the GPU passes them as a uniform array).
inline constexpr int kMaxClipPlanes = 6;

/// Up to kMaxClipPlanes planes, each with its own enabled flag, normal and offset (a
/// flipped plane is ClipPlane::flipped()). Disabled planes keep everything, so the
/// default set clips nothing. Slots are independent: the UI may disable plane 2 and keep
/// planes 0, 1 and 3 on. The plane index (0..5) is what a cap records (TrimPixel::capPlane).
struct ClipSet {
    std::array<ClipPlane, kMaxClipPlanes> planes{};

    /// Number of enabled planes.
    [[nodiscard]] int enabledCount() const;
    [[nodiscard]] bool anyEnabled() const { return enabledCount() > 0; }
    /// True when the point is kept by every enabled plane.
    [[nodiscard]] bool keeps(const glm::dvec3& p) const;

    /// Six planes keeping the axis-aligned box [lower, upper] (world space): planes 0, 1
    /// keep x >= lower.x and x <= upper.x, planes 2, 3 y, planes 4, 5 z. Unit normals
    /// pointing into the box. A box with lower > upper on some axis keeps nothing.
    [[nodiscard]] static ClipSet box(const glm::dvec3& lower, const glm::dvec3& upper);
    /// A set whose plane 0 is `plane` and whose other planes are disabled.
    [[nodiscard]] static ClipSet single(const ClipPlane& plane);

    friend bool operator==(const ClipSet&, const ClipSet&) = default;
};

/// The interval of `ray` that survives [zNear, zFar] and every enabled plane of `clips`
/// (KeptSpan, with startPlane/endPlane naming the planes that bound it). For a set whose
/// only enabled plane is plane 0 the result's tStart, tEnd, empty and startsAtNear equal
/// keptSpan(clips.planes[0], ...) bit for bit. The span is empty when nothing survives
/// (tStart > tEnd after intersecting the planes' intervals, or a plane that keeps no
/// point of [zNear, zFar]).
[[nodiscard]] KeptSpan keptSpan(const ClipSet& clips, const PixelRay& ray, double zNear, double zFar);

/// Parses up to kMaxClipPlanes "a,b,c,d" texts (the CLI's repeated --clip) into a set
/// whose planes 0.. are enabled in that order. nullopt and `error` (naming the bad plane
/// by its 1-based position) on bad input, a zero normal or too many planes.
[[nodiscard]] std::optional<ClipSet> parseClipSet(const std::vector<std::string>& texts, std::string* error);

} // namespace trimlab
