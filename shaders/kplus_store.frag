#version 430 core
// Store pass of the k+-buffer (thesis Algorithm 7.8, STORE): keeps the k nearest
// fragments of each pixel's kept span, unsorted, in a max-array or (KPLUS_HEAP) a
// max-heap, culling farther fragments before taking the per-pixel lock. The lock is a
// bounded spin-lock on imageAtomicExchange, or GL_ARB_fragment_shader_interlock
// (KPLUS_INTERLOCK_ARB) where the driver has it.
// In the same pass every fragment behind the span start updates the exact winding index.
// With KPLUS_NODE_REGION this is K+B-SB's store pass (thesis 7.1.3): the slots are the
// pixel's region of the node buffer, and the count pass before it already counted the
// winding index and the fragments of the span.
//
// No color is written and the shader ends in discard: llvmpipe drops earlier fragments
// of a tile that a later triangle fully covers when the shader looks opaque (docs/llvmpipe-notes.md).

#if defined(KPLUS_INTERLOCK_ARB)
#extension GL_ARB_fragment_shader_interlock : require
layout(pixel_interlock_ordered) in;
#define CRITICAL_BEGIN beginInvocationInterlockARB()
#define CRITICAL_END endInvocationInterlockARB()
#endif

#define KPLUS_ACCESS coherent
#include "common/kplus_storage.glsl"
#include "common/frame_counters.glsl"
#include "common/fragment_pack.glsl"
#include "common/clip.glsl"
#include "common/winding_count.glsl"
#include "common/kplus_insert.glsl"

uniform int u_maxSpin; // bounded spin: a GPU can livelock lanes of one warp on one lock

in vec3 v_viewPos;

#ifndef CRITICAL_BEGIN
layout(binding = IMAGE_SEMAPHORE, r32ui) uniform coherent uimage2D u_semaphore;

void spinLockedInsert(ivec2 pixel, uvec2 f, float depth)
{
    for (int spin = 0; spin < u_maxSpin; ++spin) {
        if (imageAtomicExchange(u_semaphore, pixel, 1u) == 0u) {
            memoryBarrier();
            insertLocked(pixel, f, depth);
            memoryBarrier();
            imageAtomicExchange(u_semaphore, pixel, 0u);
            return;
        }
    }
    atomicCounterIncrement(u_spinGiveUps);
    atomicCounterIncrement(u_fragmentsLost);
    imageStore(u_overflow, pixel, uvec4(1u));
}
#endif

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
#ifdef KPLUS_NODE_REGION
    bool kept = clipKeeps(v_viewPos);
#else
    bool kept = countWinding(pixel, v_viewPos);
    if (kept)
        atomicCounterIncrement(u_fragmentsInSpan);
#endif
    float depth = -v_viewPos.z;
    uvec2 f = packFragment(depth, uint(gl_PrimitiveID), u_objectId, gl_FrontFacing);
    beginPixelStorage(pixel);
    bool candidate = kept && !cullBeforeLock(pixel, depth);
#ifdef CRITICAL_BEGIN
    // Interlock calls must not sit in control flow: the condition goes inside.
    CRITICAL_BEGIN;
    if (candidate)
        insertLocked(pixel, f, depth);
    CRITICAL_END;
#else
    if (candidate)
        spinLockedInsert(pixel, f, depth);
#endif
    discard;
}
