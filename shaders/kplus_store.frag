#version 430 core
// Store pass of the k+-buffer with the max-array (thesis Algorithm 7.8, STORE): keeps the
// k nearest fragments of each pixel's kept span, unsorted, with the farthest at layer 0
// so that farther fragments are culled before taking the per-pixel spin-lock.
// In the same pass every fragment behind the span start adds its facing to the pixel's
// winding index, counted from the far side (core/trim/clip_plane.h): back-facing +1,
// front-facing -1. This count is exact whatever k is.
//
// The pass writes no color and ends in discard: llvmpipe drops earlier fragments of a
// tile that a later triangle fully covers when the shader looks opaque (PLATFORM.md).

#define KPLUS_ACCESS coherent
#include "common/kplus_images.glsl"
#include "common/fragment_pack.glsl"
#include "common/clip.glsl"

uniform int u_k;
uniform uint u_objectId;
uniform int u_maxSpin; // bounded spin: a GPU can livelock lanes of one warp on one lock

in vec3 v_viewPos;

uvec2 loadFragment(ivec2 pixel, int layer) { return imageLoad(u_fragments, ivec3(pixel, layer)).xy; }
void storeFragmentAt(ivec2 pixel, int layer, uvec2 f) { imageStore(u_fragments, ivec3(pixel, layer), uvec4(f, 0u, 0u)); }

// Max-array insertion while holding the pixel's lock.
void insertLocked(ivec2 pixel, uvec2 fragment, float depth)
{
    uint count = imageLoad(u_counter, pixel).r;
    if (count < uint(u_k)) {
        int slot = int(count);
        if (slot > 0) {
            uvec2 head = loadFragment(pixel, 0);
            if (depth > fragmentDepth(head)) {
                storeFragmentAt(pixel, slot, head); // the new maximum goes to layer 0
                slot = 0;
            }
        }
        storeFragmentAt(pixel, slot, fragment);
        memoryBarrierImage();
        imageStore(u_counter, pixel, uvec4(count + 1u));
        return;
    }
    imageStore(u_overflow, pixel, uvec4(1u));
    if (depth >= fragmentDepth(loadFragment(pixel, 0)))
        return; // culled: re-checked under the lock
    // The incoming fragment evicts the maximum. Find the new maximum among layers
    // 1..k-1 and the incoming fragment first, so layer 0 is written exactly once with its
    // final value: concurrent culling reads of layer 0 never see a too-small maximum.
    int maxLayer = 0;
    float maxDepth = depth;
    for (int layer = 1; layer < u_k; ++layer) {
        float d = fragmentDepth(loadFragment(pixel, layer));
        if (d > maxDepth) {
            maxDepth = d;
            maxLayer = layer;
        }
    }
    if (maxLayer == 0) {
        storeFragmentAt(pixel, 0, fragment);
    } else {
        storeFragmentAt(pixel, 0, loadFragment(pixel, maxLayer));
        storeFragmentAt(pixel, maxLayer, fragment);
    }
}

void storeFragment(ivec2 pixel, uvec2 fragment, float depth)
{
    // Fragment culling before the lock (Algorithm 7.8, line 17). Once a pixel is full its
    // counter stays at k and its maximum only decreases, so a stale read is safe.
    if (imageLoad(u_counter, pixel).r >= uint(u_k) && depth >= fragmentDepth(loadFragment(pixel, 0))) {
        imageStore(u_overflow, pixel, uvec4(1u));
        return;
    }
    for (int spin = 0; spin < u_maxSpin; ++spin) {
        if (imageAtomicExchange(u_semaphore, pixel, 1u) == 0u) {
            memoryBarrierImage();
            insertLocked(pixel, fragment, depth);
            memoryBarrierImage();
            imageAtomicExchange(u_semaphore, pixel, 0u);
            return;
        }
    }
    atomicCounterIncrement(u_spinGiveUps);
}

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    bool kept = clipKeeps(v_viewPos);
    if (kept || rayStartsAtNear(v_viewPos))
        imageAtomicAdd(u_winding, pixel, gl_FrontFacing ? -1 : 1);
    if (kept) {
        atomicCounterIncrement(u_fragmentsInSpan);
        float depth = -v_viewPos.z;
        storeFragment(pixel, packFragment(depth, uint(gl_PrimitiveID), u_objectId, gl_FrontFacing), depth);
    }
    discard;
}
