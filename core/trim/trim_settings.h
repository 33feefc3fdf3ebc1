#pragma once
/// \file
/// What the user asked the trim renderer to show. Shared by the GPU backends, the CPU
/// reference, the GUI and the command line so that all of them mean the same thing.

#include "trim/clip_plane.h"
#include "trim/static_rule.h"

namespace trimlab {

struct TrimSettings {
    /// Off: standard rendering, the first surface point of the kept part of each ray.
    /// On: the first point whose two sides classify differently under `rule`.
    bool trimEnabled = true;
    StaticRule rule = StaticRule::AlternatingBorder;
    ClipPlane clip;
    friend bool operator==(const TrimSettings&, const TrimSettings&) = default;
};

} // namespace trimlab
