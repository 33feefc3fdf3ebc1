#version 430 core
// Clear pass of the per-pixel state (Algorithm 7.8, CLEAR): counters, locks, winding
// index and overflow flags back to zero. Fragment slots need no clearing: only the
// first `counter` of a pixel are ever read. Shared by every method that keeps such state.


layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = IMAGE_COUNTER, r32ui) uniform writeonly uimage2D u_counter;
layout(binding = IMAGE_SEMAPHORE, r32ui) uniform writeonly uimage2D u_semaphore;
layout(binding = IMAGE_WINDING, r32i) uniform writeonly iimage2D u_winding;
layout(binding = IMAGE_OVERFLOW, r32ui) uniform writeonly uimage2D u_overflow;

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
