#version 430 core
// Store pass of AB_FP, the A-buffer with fixed-size per-pixel arrays (thesis 2.4.2,
// Figure 2.6 a): the pixel's counter, atomically incremented, gives each fragment of the
// kept span the next of the k slots, in order of arrival. Fragments beyond k are lost:
// counted, and the pixel's overflow image keeps the NEAREST lost depth, encoded as
// ~floatBits(depth) under imageAtomicMax (depths are positive, so a larger code is a
// nearer depth and 0 means nothing lost). The resolve needs it to decide whether the
// arbitrary k fragments it kept can still prove the trim point (abuffer_fixed_resolve.frag).
// The same pass counts the exact winding index. No color; ends in discard (docs/llvmpipe-notes.md).

#include "common/frame_counters.glsl"
#include "common/fragment_pack.glsl"
#include "common/clip.glsl"
#include "common/winding_count.glsl"

layout(binding = IMAGE_COUNTER, r32ui) uniform coherent uimage2D u_counter;
layout(binding = IMAGE_OVERFLOW, r32ui) uniform coherent uimage2D u_overflow;
layout(binding = IMAGE_FRAGMENTS, rg32ui) uniform writeonly uimage2DArray u_fragments;

uniform int u_k;

in vec3 v_viewPos;

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (countWinding(pixel, v_viewPos)) {
        atomicCounterIncrement(u_fragmentsInSpan);
        float depth = -v_viewPos.z;
        uint slot = imageAtomicAdd(u_counter, pixel, 1u);
        if (slot < uint(u_k)) {
            uvec2 f = packFragment(depth, uint(gl_PrimitiveID), u_objectId, gl_FrontFacing);
            imageStore(u_fragments, ivec3(pixel, int(slot)), uvec4(f, 0u, 0u));
            atomicCounterIncrement(u_fragmentsStored);
        } else {
            atomicCounterIncrement(u_fragmentsLost);
            imageAtomicMax(u_overflow, pixel, ~floatBitsToUint(depth));
        }
    }
    discard;
}
