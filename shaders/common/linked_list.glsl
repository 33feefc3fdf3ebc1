// The per-pixel linked lists of AB_LL (thesis 2.4.2, Figure 2.6 b; render/mfr/
// abuffer_linked_list.h): one node buffer for all fragments, a parallel buffer of next
// links, a head image pointing at each pixel's most recent fragment, and one global
// node counter. Heads and links hold node index + 1, so 0 ends a list.
// The includer defines LIST_ACCESS.

layout(binding = IMAGE_HEAD, r32ui) uniform LIST_ACCESS uimage2D u_head;
layout(std430, binding = STORAGE_NODES) LIST_ACCESS buffer ListNodes { uvec2 nodes[]; };
layout(std430, binding = STORAGE_LINKS) LIST_ACCESS buffer ListLinks { uint links[]; };

const uint LIST_END = 0u;
