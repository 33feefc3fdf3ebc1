#version 430 core
// Memory referencing of the S-buffer and K+B-SB, step 1 (thesis equation 5.1): every
// non-empty pixel takes `n` nodes from the shared counter of its hash group,
// p.address = atomicAdd(C(H(p)), n), and keeps the address in the head image. n is the
// pixel's fragment count f(p), bounded by u_regionLimit (k for K+B-SB).

#define SHARED_COUNTERS_ACCESS coherent
#include "common/shared_counters.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = IMAGE_COUNTER, r32ui) uniform readonly uimage2D u_counter;
layout(binding = IMAGE_HEAD, r32ui) uniform writeonly uimage2D u_head;

uniform ivec2 u_size;
uniform uint u_regionLimit;

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, u_size)))
        return;
    uint n = min(imageLoad(u_counter, pixel).r, u_regionLimit);
    uint address = 0u;
    if (n > 0u)
        address = atomicAdd(sharedCounters[counterIndex(pixelHash(pixel, u_size))], n);
    imageStore(u_head, pixel, uvec4(address));
}
