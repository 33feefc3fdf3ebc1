#version 430 core
// Clears the per-pixel head image of the linked-list A-buffer: 0 is the empty list
// (heads and links hold node index + 1).


layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = IMAGE_HEAD, r32ui) uniform writeonly uimage2D u_head;

uniform ivec2 u_size;

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (all(lessThan(pixel, u_size)))
        imageStore(u_head, pixel, uvec4(0u));
}
