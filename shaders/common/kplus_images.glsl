// The k+-buffer's per-pixel state (render/mfr/kplus_buffer.h binds these image units).
// Each stage declares the access it needs by defining KPLUS_ACCESS before including:
// "coherent" for the store pass, "readonly" for resolve.

layout(binding = 0, r32ui) uniform KPLUS_ACCESS uimage2D u_counter;    // fragments held (<= k)
layout(binding = 1, r32ui) uniform KPLUS_ACCESS uimage2D u_semaphore;  // spin-lock, 0 = free
layout(binding = 2, r32i) uniform KPLUS_ACCESS iimage2D u_winding;     // winding index at span start
layout(binding = 3, r32ui) uniform KPLUS_ACCESS uimage2D u_overflow;   // 1 once more than k arrived
layout(binding = 4, rg32ui) uniform KPLUS_ACCESS uimage2DArray u_fragments; // k layers, max at layer 0

// Frame counters (render/frame_counters.h): one atomic_uint each, in this order.
layout(binding = 0, offset = 0) uniform atomic_uint u_fragmentsInSpan;
layout(binding = 0, offset = 4) uniform atomic_uint u_overflowPixels;
layout(binding = 0, offset = 8) uniform atomic_uint u_unresolvedPixels;
layout(binding = 0, offset = 12) uniform atomic_uint u_spinGiveUps;
