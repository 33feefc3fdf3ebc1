#version 430 core
// Resolve pass of AB_FP: sort the k slots of the pixel in registers and walk them front
// to back from the exact winding index at the span start.
// An overflowed pixel kept the first k fragments to ARRIVE, not the k nearest, so a trim
// fragment its walk finds may be wrong: a lost fragment in front of it would have
// changed the winding index on the way. The store pass recorded the nearest lost depth;
// every fragment nearer than that was kept, so the walk is exact up to there. The pixel
// is shown only when its trim fragment lies strictly in front of the nearest lost one
// (then provably right); otherwise it is unresolved (counted, magenta).

#include "common/frame_counters.glsl"
#include "common/fragment_pack.glsl"
#include "common/static_rule.glsl"
#include "common/trim_walk.glsl"
#include "common/trim_shading.glsl"
#include "common/scene_data.glsl"
#include "common/trim_output.glsl"
#include "common/pixel_result.glsl"

layout(binding = IMAGE_COUNTER, r32ui) uniform readonly uimage2D u_counter;
layout(binding = IMAGE_OVERFLOW, r32ui) uniform readonly uimage2D u_overflow;
layout(binding = IMAGE_WINDING, r32i) uniform readonly iimage2D u_winding;
layout(binding = IMAGE_FRAGMENTS, rg32ui) uniform readonly uimage2DArray u_fragments;

#ifndef K_MAX
#error K_MAX (the k of AB_FP) must be defined
#endif
uvec2 g_fragments[K_MAX];
#include "common/fragment_sort.glsl"

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    int count = int(min(imageLoad(u_counter, pixel).r, uint(K_MAX)));
    for (int i = 0; i < count; ++i)
        g_fragments[i] = imageLoad(u_fragments, ivec3(pixel, i)).xy;
    sortFragments(count);

    int windingAtStart = imageLoad(u_winding, pixel).r;
    uint lostCode = imageLoad(u_overflow, pixel).r;
    bool overflowed = lostCode != 0u;
    TrimWalk walk = beginTrimWalk(windingAtStart);
    for (int i = 0; i < count; ++i)
        if (trimWalkStep(walk, g_fragments[i]))
            break;
    bool certain = !overflowed || (walk.found && fragmentDepth(walk.shown) < uintBitsToFloat(~lostCode));
    emitWalkResult(walk, certain, windingAtStart, overflowed);
}
