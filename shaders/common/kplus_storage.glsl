// The k+-buffer's per-pixel storage: the slots, the number held, a spin-lock and an
// overflow flag. Slot 0 always holds the farthest fragment (max-array) or the heap root
// (max-heap), so a fragment can be culled against it in O(1). The includer defines
// KPLUS_ACCESS. Two places for the slots:
// - default (render/mfr/kplus_buffer.h): the k layers of an RG32UI array texture;
// - KPLUS_NODE_REGION (K+B-SB, render/mfr/kplus_s_buffer.h, thesis 7.1.3): the pixel's
//   variable region of the node buffer, min(f(p), k) nodes from u_head(pixel) on.
// Call beginPixelStorage(pixel) once before any slot access.

layout(binding = IMAGE_COUNTER, r32ui) uniform KPLUS_ACCESS uimage2D u_counter;
layout(binding = IMAGE_OVERFLOW, r32ui) uniform KPLUS_ACCESS uimage2D u_overflow;

#ifdef KPLUS_NODE_REGION
layout(binding = IMAGE_HEAD, r32ui) uniform readonly uimage2D u_head;
layout(std430, binding = STORAGE_NODES) KPLUS_ACCESS buffer KPlusNodes { uvec2 nodes[]; };

uint g_regionStart; // first node of this pixel's region

void beginPixelStorage(ivec2 pixel) { g_regionStart = imageLoad(u_head, pixel).r; }
uvec2 loadSlot(ivec2 pixel, int slot) { return nodes[g_regionStart + uint(slot)]; }
#else
layout(binding = IMAGE_FRAGMENTS, rg32ui) uniform KPLUS_ACCESS uimage2DArray u_fragments;

void beginPixelStorage(ivec2 pixel) {}
uvec2 loadSlot(ivec2 pixel, int slot) { return imageLoad(u_fragments, ivec3(pixel, slot)).xy; }
#endif
