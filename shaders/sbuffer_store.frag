#version 430 core
// Fragment storing pass of the S-buffer (thesis 5.1.3): every fragment of a pixel's kept
// span goes, unsorted, to the next free node of the pixel's region (the head image holds
// the region's first node, the counter the nodes taken so far). No lock is needed.
// The region was sized by the count pass, which rasterised the same geometry with the
// same vertex shader (scene.vert's gl_Position is invariant), so it never overflows; a
// node beyond the buffer would still be counted as lost and its pixel flagged, never
// written out of bounds.
// No color is written and the shader ends in discard (docs/llvmpipe-notes.md).

#include "common/frame_counters.glsl"
#include "common/fragment_pack.glsl"
#include "common/clip.glsl"

layout(binding = IMAGE_COUNTER, r32ui) uniform coherent uimage2D u_counter;
layout(binding = IMAGE_HEAD, r32ui) uniform readonly uimage2D u_head;
layout(binding = IMAGE_OVERFLOW, r32ui) uniform writeonly uimage2D u_overflow;
layout(std430, binding = STORAGE_NODES) writeonly buffer Nodes { uvec2 nodes[]; };

uniform uint u_objectId;
uniform uint u_nodeCapacity;

in vec3 v_viewPos;

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (clipKeeps(v_viewPos)) {
        uint node = imageLoad(u_head, pixel).r + imageAtomicAdd(u_counter, pixel, 1u);
        if (node < u_nodeCapacity) {
            nodes[node] = packFragment(-v_viewPos.z, uint(gl_PrimitiveID), u_objectId, gl_FrontFacing);
            atomicCounterIncrement(u_fragmentsStored);
        } else {
            atomicCounterIncrement(u_fragmentsLost);
            imageStore(u_overflow, pixel, uvec4(1u));
        }
    }
    discard;
}
