#version 430 core
// Resolve pass of the two-pass method: one step of the shared trim walk from the exact
// winding index at the span start, fed the nearest fragment of the span. If that fragment
// is a trim boundary it is the answer. If not, the trim lies deeper (a self-crossing
// surface seen through an interior sheet) and two passes cannot tell where: the pixel is
// flagged overflowed and unresolved, counted, painted UNRESOLVED_COLOR, and the span's
// other fragments, which the method never looked at, are counted as lost. With CAPPING a
// pixel whose span starts inside the solid at a clipping plane shows the cap (cap.glsl).

#include "common/frame_counters.glsl"
#include "common/fragment_pack.glsl"
#include "common/static_rule.glsl"
#include "common/trim_walk.glsl"
#include "common/trim_shading.glsl"
#include "common/scene_data.glsl"
#include "common/trim_output.glsl"

layout(binding = IMAGE_WINDING, r32i) uniform readonly iimage2D u_winding;
layout(binding = IMAGE_COUNTER, r32ui) uniform readonly uimage2D u_counter;
layout(binding = IMAGE_OVERFLOW, r32ui) uniform writeonly uimage2D u_overflow;

uniform usampler2D u_closest; // the closest pass's packed fragment; x = 0: none

#ifdef CAPPING
#include "common/cap.glsl"
#endif

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    int start = imageLoad(u_winding, pixel).r;
    uvec2 closest = texelFetch(u_closest, pixel, 0).xy;
#ifdef CAPPING
    // The cap needs only the exact index at the span start (counted by the first pass).
    if (emitCapIfShown(u_trimEnabled && isInterior(u_rule, start), start, false))
        return;
#endif
    if (closest.x == 0u) {
        emitEmptyPixel(start, false, false);
        return;
    }
    atomicCounterIncrement(u_fragmentsStored);
    TrimWalk walk = beginTrimWalk(start);
    if (trimWalkStep(walk, closest)) {
        emitShownPixel(closest, start, false);
        return;
    }
    imageStore(u_overflow, pixel, uvec4(1u));
    atomicCounterIncrement(u_overflowPixels);
    atomicCounterIncrement(u_unresolvedPixels);
    for (uint i = 1u; i < imageLoad(u_counter, pixel).r; ++i)
        atomicCounterIncrement(u_fragmentsLost);
    emitEmptyPixel(start, true, true);
}
