#version 430 core
// Resolve pass of the k+-buffer (thesis Algorithm 7.8, RESOLVE, with the trimming of
// 8.1.2): sort the pixel's slots in registers and walk them front to back from the exact
// winding index at the span start. A pixel that overflowed is still exact when its trim
// point is among the k nearest; otherwise it is unresolved (counted, painted magenta).
// With KPLUS_NODE_REGION it resolves K+B-SB, whose slots are a node-buffer region.

#define KPLUS_ACCESS readonly
#include "common/kplus_storage.glsl"
#include "common/frame_counters.glsl"
#include "common/fragment_pack.glsl"
#include "common/static_rule.glsl"
#include "common/trim_walk.glsl"
#include "common/trim_shading.glsl"
#include "common/scene_data.glsl"
#include "common/trim_output.glsl"
#include "common/pixel_result.glsl"

layout(binding = IMAGE_WINDING, r32i) uniform readonly iimage2D u_winding;

#ifndef K_MAX
#error K_MAX (the k of the k+-buffer) must be defined
#endif
uvec2 g_fragments[K_MAX];
#include "common/fragment_sort.glsl"

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    int count = int(min(imageLoad(u_counter, pixel).r, uint(K_MAX)));
    beginPixelStorage(pixel);
    for (int i = 0; i < count; ++i)
        g_fragments[i] = loadSlot(pixel, i);
    sortFragments(count);

    int windingAtStart = imageLoad(u_winding, pixel).r;
    bool overflowed = imageLoad(u_overflow, pixel).r != 0u;
    TrimWalk walk = beginTrimWalk(windingAtStart);
    for (int i = 0; i < count && !trimWalkStep(walk, g_fragments[i]); ++i) {
    }
    // Found among the k nearest: exact even if farther fragments were lost.
    emitWalkResult(walk, walk.found || !overflowed, windingAtStart, overflowed);
}
