#version 430 core
// Resolve pass of the S-buffer (thesis 5.1.3): the pixel's region of the node buffer is
// sorted by depth and walked front to back from the exact winding index at the span
// start (trim_walk.glsl). Lists of up to LIST_MAX fragments are sorted in registers
// (insertion sort up to 16, shell sort above, fragment_sort.glsl); longer ones, which a
// register array of that size cannot hold, are shell-sorted in place in the node buffer
// and walked from there: slower and exact. Only where that sort would run past the
// driver's loop limit (llvmpipe, resolve_budget.glsl: lists of thousands of fragments)
// is the pixel reported unresolved (counted, magenta) instead of shown half sorted.

#include "common/frame_counters.glsl"
#include "common/fragment_pack.glsl"
#include "common/static_rule.glsl"
#include "common/trim_walk.glsl"
#include "common/trim_shading.glsl"
#include "common/scene_data.glsl"
#include "common/trim_output.glsl"
#include "common/pixel_result.glsl"
#include "common/resolve_budget.glsl"

layout(binding = IMAGE_COUNTER, r32ui) uniform readonly uimage2D u_counter;
layout(binding = IMAGE_HEAD, r32ui) uniform readonly uimage2D u_head;
layout(binding = IMAGE_OVERFLOW, r32ui) uniform readonly uimage2D u_overflow;
layout(binding = IMAGE_WINDING, r32i) uniform readonly iimage2D u_winding;
layout(std430, binding = STORAGE_NODES) buffer Nodes { uvec2 nodes[]; };

uniform uint u_nodeCapacity;

#ifndef LIST_MAX
#error LIST_MAX (the register array of the resolve) must be defined
#endif
uvec2 g_fragments[LIST_MAX];
#include "common/fragment_sort.glsl"
#include "common/node_sort.glsl"

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    uint start = imageLoad(u_head, pixel).r;
    // Within the buffer also if a store pass ever disagreed with the count (then flagged).
    int count = int(min(imageLoad(u_counter, pixel).r, u_nodeCapacity - min(start, u_nodeCapacity)));
    int windingAtStart = imageLoad(u_winding, pixel).r;
    bool overflowed = imageLoad(u_overflow, pixel).r != 0u;

    TrimWalk walk = beginTrimWalk(windingAtStart);
    bool sorted = true;
    if (count <= LIST_MAX) {
        for (int i = 0; i < count; ++i)
            g_fragments[i] = nodes[start + uint(i)];
        sortFragments(count);
        for (int i = 0; i < count; ++i)
            if (trimWalkStep(walk, g_fragments[i]))
                break;
    } else {
        int budget = u_loopBudget - count; // leaves the walk's iterations
        sorted = shellSortNodes(start, count, budget);
        for (int i = 0; sorted && i < count; ++i)
            if (trimWalkStep(walk, nodes[start + uint(i)]))
                break;
    }
    // Overflow is only possible if a store pass disagreed with the count pass; the lost
    // fragments may then lie at any depth.
    emitWalkResult(walk, sorted && !overflowed, windingAtStart, overflowed);
}
