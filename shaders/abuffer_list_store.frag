#version 430 core
// Store pass of AB_LL (Yang et al., thesis 2.4.2): every fragment of the kept span takes
// the next node from the global counter and is pushed on its pixel's list by exchanging
// the head. When the node buffer is full the fragment is lost (counted, pixel flagged)
// but the counter still counts it: the renderer reads the counter back, grows the buffer
// to what the frame needs and renders the frame again (render/mfr/abuffer_linked_list.h).
// The pass also counts the exact winding index and the pixel's fragments (the resolve
// and readOccupancy use the count). No color; ends in discard (docs/llvmpipe-notes.md).

#include "common/frame_counters.glsl"
#include "common/fragment_pack.glsl"
#include "common/clip.glsl"
#include "common/winding_count.glsl"
#define LIST_ACCESS coherent
#include "common/linked_list.glsl"

layout(binding = IMAGE_COUNTER, r32ui) uniform coherent uimage2D u_counter;
layout(binding = IMAGE_OVERFLOW, r32ui) uniform writeonly uimage2D u_overflow;
layout(std430, binding = STORAGE_SHARED_COUNTERS) coherent buffer NodeCounter { uint nodeCounter; };

uniform uint u_nodeCapacity;

in vec3 v_viewPos;

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (countWinding(pixel, v_viewPos)) {
        atomicCounterIncrement(u_fragmentsInSpan);
        imageAtomicAdd(u_counter, pixel, 1u);
        uint node = atomicAdd(nodeCounter, 1u);
        if (node < u_nodeCapacity) {
            nodes[node] = packFragment(-v_viewPos.z, uint(gl_PrimitiveID), u_objectId, gl_FrontFacing);
            links[node] = imageAtomicExchange(u_head, pixel, node + 1u);
            atomicCounterIncrement(u_fragmentsStored);
        } else {
            atomicCounterIncrement(u_fragmentsLost);
            imageStore(u_overflow, pixel, uvec4(1u));
        }
    }
    discard;
}
