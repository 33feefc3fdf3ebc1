#version 430 core
// Resolve pass of F2B and DUAL: the answer the front trim walk holds. A pixel still
// peeling when the pass bound (MethodParameters::maxPeelingPasses) stopped the frame, or
// whose DUAL walks disagreed, cannot be known: it is flagged overflowed and unresolved,
// counted, and its unpeeled fragments are counted as lost. Such pixels are painted
// UNRESOLVED_COLOR, never shown wrong. With CAPPING a pixel whose span starts inside the
// solid at a clipping plane shows the cap (cap.glsl).

#include "common/frame_counters.glsl"
#include "common/fragment_pack.glsl"
#include "common/static_rule.glsl"
#include "common/trim_walk.glsl"
#include "common/trim_shading.glsl"
#include "common/scene_data.glsl"
#include "common/trim_output.glsl"
#include "common/peel_state.glsl"
#include "common/peel_walk_state.glsl"

#ifdef CAPPING
#include "common/cap.glsl"
#endif

layout(binding = IMAGE_OVERFLOW, r32ui) uniform writeonly uimage2D u_overflow;

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    PeelWalk front = loadPeelWalk(pixel, WALK_FRONT);
    int start = windingAtStart(pixel);
#ifdef CAPPING
    // The cap needs only the exact index at the span start, not the peeled fragments.
    if (emitCapIfShown(u_trimEnabled && isInterior(u_rule, start), start, false))
        return;
#endif
    if (front.done && !front.inconsistent) {
        if (front.walk.found)
            emitShownPixel(front.walk.shown, start, false);
        else
            emitEmptyPixel(start, false, false);
        return;
    }
    imageStore(u_overflow, pixel, uvec4(1u));
    atomicCounterIncrement(u_overflowPixels);
    atomicCounterIncrement(u_unresolvedPixels);
    for (uint i = peeledCount(pixel); i < spanCount(pixel); ++i)
        atomicCounterIncrement(u_fragmentsLost);
    emitEmptyPixel(start, true, true);
}
