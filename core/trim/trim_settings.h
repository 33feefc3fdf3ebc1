#pragma once
/// \file
/// What the user asked the trim renderer to show. Shared by the GPU backends, the CPU
/// reference, the GUI and the command line so that all of them mean the same thing.

#include "core/trim/clip_plane.h"
#include "core/trim/clip_set.h"
#include "core/trim/inspect_settings.h"
#include "core/trim/static_rule.h"

#include <array>

namespace trimlab {

struct TrimSettings {
    /// Off: standard rendering, the first surface point of the kept part of each ray.
    /// On: the first point whose two sides classify differently under `rule` (or under
    /// the CSG expression, see `csg`).
    bool trimEnabled = true;
    StaticRule rule = StaticRule::AlternatingBorder;
    /// Clipping plane 0 (the one plane of earlier versions; the GUI's clip row edits it).
    ClipPlane clip;
    /// Clipping planes 1 .. kMaxClipPlanes − 1; all disabled by default. Together with
    /// `clip` they form clipSet(), which every renderer uses.
    std::array<ClipPlane, kMaxClipPlanes - 1> moreClips{};
    /// Capping where the kept span starts at a clipping plane inside the solid.
    CapSettings cap;
    /// CSG over the scene's objects and per-object rules (no expression: one surface).
    CsgSettings csg;
    /// Collision and coplanarity highlighting of the shown fragments.
    HighlightSettings highlight;
    /// Transparency / X-ray over the kept span's fragments (off by default).
    TransparencySettings transparency;

    /// All clipping planes as one set: plane 0 is `clip`, plane i > 0 is moreClips[i − 1].
    [[nodiscard]] ClipSet clipSet() const
    {
        ClipSet set;
        set.planes[0] = clip;
        for (int i = 1; i < kMaxClipPlanes; ++i)
            set.planes[std::size_t(i)] = moreClips[std::size_t(i - 1)];
        return set;
    }
    /// Replaces every clipping plane by those of `set`.
    void setClipSet(const ClipSet& set)
    {
        clip = set.planes[0];
        for (int i = 1; i < kMaxClipPlanes; ++i)
            moreClips[std::size_t(i - 1)] = set.planes[std::size_t(i)];
    }
    /// Plane `index` (0 .. kMaxClipPlanes − 1) of clipSet(), for editing in place.
    [[nodiscard]] ClipPlane& clipPlane(int index) { return index == 0 ? clip : moreClips[std::size_t(index - 1)]; }
    [[nodiscard]] const ClipPlane& clipPlane(int index) const
    {
        return index == 0 ? clip : moreClips[std::size_t(index - 1)];
    }

    /// The rule that classifies object `objectId` on its own (csg.objectRules, else `rule`).
    [[nodiscard]] StaticRule objectRule(int objectId) const
    {
        if (objectId >= 0 && objectId < kMaxCsgOperands)
            if (const auto& own = csg.objectRules[std::size_t(objectId)])
                return *own;
        return rule;
    }
    /// True when a pixel needs one winding index per object (CSG or collision
    /// highlighting; only with trimming on).
    [[nodiscard]] bool perObjectWinding() const { return trimEnabled && (csg.enabled() || highlight.collisions); }
    /// True when caps can show (capping on, trimming on, some plane enabled).
    [[nodiscard]] bool capping() const { return cap.enabled && trimEnabled && clipSet().anyEnabled(); }
    /// True when the colors composite the span's layers (TransparencySettings).
    [[nodiscard]] bool xray() const { return transparency.enabled; }

    friend bool operator==(const TrimSettings&, const TrimSettings&) = default;
};

} // namespace trimlab
