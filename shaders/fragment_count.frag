#version 430 core
// Fragment count pass of the S-buffer (thesis 5.1.1) and of K+B-SB (Algorithm 7.8,
// COUNT): every fragment of a pixel's kept span adds one to the pixel's counter f(p),
// and every fragment behind the span start updates the exact winding index. The counter
// is not bounded by k here: K+B-SB's referencing pass allocates min(f(p), k) and knows
// from f(p) > k, exactly, which pixels overflow.
// No color is written and the shader ends in discard (docs/llvmpipe-notes.md).

#include "common/frame_counters.glsl"
#include "common/clip.glsl"
#include "common/winding_count.glsl"

layout(binding = IMAGE_COUNTER, r32ui) uniform coherent uimage2D u_counter;

in vec3 v_viewPos;

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (countWinding(pixel, v_viewPos)) {
        imageAtomicAdd(u_counter, pixel, 1u);
        atomicCounterIncrement(u_fragmentsInSpan);
    }
    discard;
}
