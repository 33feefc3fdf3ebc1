#version 430 core
// Clear pass of the k+-buffer (Algorithm 7.8, CLEAR): counters, locks, winding index and
// overflow flags back to zero. The fragment layers need no clearing: only the first
// `counter` entries of a pixel are ever read.

layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = 0, r32ui) uniform writeonly uimage2D u_counter;
layout(binding = 1, r32ui) uniform writeonly uimage2D u_semaphore;
layout(binding = 2, r32i) uniform writeonly iimage2D u_winding;
layout(binding = 3, r32ui) uniform writeonly uimage2D u_overflow;

uniform ivec2 u_size;

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, u_size)))
        return;
    imageStore(u_counter, pixel, uvec4(0u));
    imageStore(u_semaphore, pixel, uvec4(0u));
    imageStore(u_winding, pixel, ivec4(0));
    imageStore(u_overflow, pixel, uvec4(0u));
}
