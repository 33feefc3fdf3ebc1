#version 430 core
// Resolve pass of AB_LL: the pixel's list is copied into registers, sorted (insertion
// sort up to 16, shell sort above) and walked front to back from the exact winding
// index at the span start. A list longer than the register array (LIST_MAX) is sorted
// in place by relinking (common/list_sort.glsl) and walked along its links; only where
// that would run past the driver's loop limit (llvmpipe, resolve_budget.glsl) is the
// pixel reported unresolved instead.
// A pixel that lost fragments (possible only if the frame overflowed again after the
// node buffer grew) is never shown but reported unresolved: its list may miss fragments
// at any depth. Lists are walked at most `count` nodes deep.

#include "common/frame_counters.glsl"
#include "common/fragment_pack.glsl"
#include "common/static_rule.glsl"
#include "common/trim_walk.glsl"
#include "common/trim_shading.glsl"
#include "common/scene_data.glsl"
#include "common/trim_output.glsl"
#include "common/pixel_result.glsl"
#include "common/resolve_budget.glsl"
#define LIST_ACCESS restrict
#include "common/linked_list.glsl"
#include "common/list_sort.glsl"

layout(binding = IMAGE_COUNTER, r32ui) uniform readonly uimage2D u_counter;
layout(binding = IMAGE_OVERFLOW, r32ui) uniform readonly uimage2D u_overflow;
layout(binding = IMAGE_WINDING, r32i) uniform readonly iimage2D u_winding;

#ifndef LIST_MAX
#error LIST_MAX (the register array of the resolve) must be defined
#endif
uvec2 g_fragments[LIST_MAX];
#include "common/fragment_sort.glsl"

void walkInRegisters(uint head, int count, inout TrimWalk walk)
{
    int n = 0;
    for (uint link = head; link != LIST_END && n < count; link = nextLink(link))
        g_fragments[n++] = nodes[link - 1u];
    sortFragments(n);
    for (int i = 0; i < n; ++i)
        if (trimWalkStep(walk, g_fragments[i]))
            break;
}

// False when the list could not be sorted within the loop budget.
bool walkSortedList(uint head, int count, inout TrimWalk walk)
{
    int budget = u_loopBudget - count; // leaves the walk's iterations
    if (!mergeSortList(head, budget))
        return false;
    int n = 0;
    for (uint link = head; link != LIST_END && n < count; link = nextLink(link), ++n)
        if (trimWalkStep(walk, nodes[link - 1u]))
            break;
    return true;
}

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    int count = int(imageLoad(u_counter, pixel).r);
    uint head = imageLoad(u_head, pixel).r;
    int windingAtStart = imageLoad(u_winding, pixel).r;
    bool overflowed = imageLoad(u_overflow, pixel).r != 0u;

    TrimWalk walk = beginTrimWalk(windingAtStart);
    bool sorted = true;
    if (!overflowed) {
        if (count <= LIST_MAX)
            walkInRegisters(head, count, walk);
        else
            sorted = walkSortedList(head, count, walk);
    }
    emitWalkResult(walk, sorted && !overflowed, windingAtStart, overflowed);
}
