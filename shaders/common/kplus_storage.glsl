// The k+-buffer's per-pixel storage (render/mfr/kplus_buffer.h binds it): the k slots
// of an RG32UI array texture, the number held, a spin-lock and an overflow flag. Slot 0
// always holds the farthest fragment (max-array) or the heap root (max-heap), so a
// fragment can be culled against it in O(1). The includer defines KPLUS_ACCESS.

layout(binding = IMAGE_COUNTER, r32ui) uniform KPLUS_ACCESS uimage2D u_counter;
layout(binding = IMAGE_OVERFLOW, r32ui) uniform KPLUS_ACCESS uimage2D u_overflow;
layout(binding = IMAGE_FRAGMENTS, rg32ui) uniform KPLUS_ACCESS uimage2DArray u_fragments;

uvec2 loadSlot(ivec2 pixel, int slot) { return imageLoad(u_fragments, ivec3(pixel, slot)).xy; }
