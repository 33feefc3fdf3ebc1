#version 430 core
// First geometry pass of the two-pass method (thesis Algorithm 8.9,
// IndexClassificationStatic): the winding index at the start of the kept span as a
// signed count of fragments, without sorting. Algorithm 8.9 sums the fragments in front
// of the span start (+1 front-facing, -1 back-facing) with ADD blending; this pass sums
// those behind it (+1 back-facing, -1 front-facing) with the shared countWinding. For
// closed surfaces and an eye outside every solid the two sums are equal: a ray from the
// eye to infinity starts and ends at index 0, so its front and back crossings cancel and
// the crossings in front of a point equal minus those behind it. The far-side sum stays
// exact where the front-side one is not (the eye inside a solid, surfaces cut off by the
// near plane), which is why every TrimLab method counts it. The static rule is applied
// in the resolve pass.
// Also counts each pixel's span fragments, so the resolve can report how many the two
// passes could not look at. No color is written and the shader ends in discard.

#include "common/frame_counters.glsl"
#include "common/clip.glsl"
#include "common/winding_count.glsl"

layout(binding = IMAGE_COUNTER, r32ui) uniform coherent uimage2D u_counter;

in vec3 v_viewPos;

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (countWinding(pixel, v_viewPos)) {
        atomicCounterIncrement(u_fragmentsInSpan);
        imageAtomicAdd(u_counter, pixel, 1u);
    }
    discard;
}
