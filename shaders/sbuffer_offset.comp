#version 430 core
// Memory referencing, step 3 (thesis equation 5.2): the pixel's region in the node
// buffer. With A(p) = p.address + Cpr(H(p)), a pixel of G1 starts at A(p); a pixel of G2
// counts from the end of the buffer: the thesis's offset total - 1 - A(p) is the LAST
// node of its region, so the region is [total - A(p) - n, total - A(p)). G1 fills
// [0, ΣG1) and G2 [ΣG1, total), both exactly.
// The head image then holds the region's first node; the counter restarts at zero to
// guide the store pass (Algorithm 7.8, REFERENCING); pixels with f(p) > u_regionLimit
// are flagged overflowed (K+B-SB keeps only their k nearest fragments).

#define SHARED_COUNTERS_ACCESS readonly
#include "common/shared_counters.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = IMAGE_COUNTER, r32ui) uniform uimage2D u_counter;
layout(binding = IMAGE_HEAD, r32ui) uniform uimage2D u_head;
layout(binding = IMAGE_OVERFLOW, r32ui) uniform writeonly uimage2D u_overflow;

uniform ivec2 u_size;
uniform uint u_regionLimit;

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, u_size)))
        return;
    uint f = imageLoad(u_counter, pixel).r;
    uint n = min(f, u_regionLimit);
    uint start = 0u;
    if (n > 0u) {
        uint group = pixelHash(pixel, u_size);
        uint A = imageLoad(u_head, pixel).r + sharedCounters[prefixIndex(group)];
        start = inForwardGroup(group) ? A : sharedCounters[totalIndex()] - A - n;
    }
    imageStore(u_head, pixel, uvec4(start));
    imageStore(u_counter, pixel, uvec4(0u));
    if (f > u_regionLimit)
        imageStore(u_overflow, pixel, uvec4(1u));
}
