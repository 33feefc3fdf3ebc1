// Per-frame statistics the shaders increment (render/frame/frame_counters.h reads them back).
layout(binding = ATOMIC_FRAME_COUNTERS, offset = 0) uniform atomic_uint u_fragmentsInSpan;  // fragments in the kept span
layout(binding = ATOMIC_FRAME_COUNTERS, offset = 4) uniform atomic_uint u_overflowPixels;   // pixels that lost fragments
layout(binding = ATOMIC_FRAME_COUNTERS, offset = 8) uniform atomic_uint u_unresolvedPixels; // of those, trim point lost
layout(binding = ATOMIC_FRAME_COUNTERS, offset = 12) uniform atomic_uint u_spinGiveUps;     // fragments that gave up the lock
layout(binding = ATOMIC_FRAME_COUNTERS, offset = 16) uniform atomic_uint u_fragmentsLost;   // fragments not stored (capacity)
layout(binding = ATOMIC_FRAME_COUNTERS, offset = 20) uniform atomic_uint u_fragmentsStored; // fragments written to storage
layout(binding = ATOMIC_FRAME_COUNTERS, offset = 24) uniform atomic_uint u_capPixels;       // pixels showing a cap
layout(binding = ATOMIC_FRAME_COUNTERS, offset = 28) uniform atomic_uint u_collisionPixels; // shown fragments highlighted as colliding
layout(binding = ATOMIC_FRAME_COUNTERS, offset = 32) uniform atomic_uint u_coplanarPixels;  // shown fragments in a coplanar group (>= 2)
