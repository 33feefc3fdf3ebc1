#version 430 core
// Clear pass of the depth-peeling state (common/peel_state.glsl): every cursor field to
// its initial value and every trim walk to "not started". The per-pixel counter,
// winding and overflow images have their own clear (pixel_state_clear.comp).

#include "common/peel_state.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

uniform ivec2 u_size;
uniform int u_peelLayers; // PEEL_LAYERS_F2B or PEEL_LAYERS_DUAL
uniform int u_walkLayers; // 1 (F2B) or 2 (DUAL)

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, u_size)))
        return;
    for (int field = 0; field < u_peelLayers; ++field)
        peelStore(pixel, field, peelInitialValue(field));
    for (int layer = 0; layer < u_walkLayers; ++layer)
        imageStore(u_walk, ivec3(pixel, layer), uvec4(0u));
}
