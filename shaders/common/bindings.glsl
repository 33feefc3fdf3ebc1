// Binding points shared by every multi-fragment method (C++ mirror: render/mfr/bindings.h).
// Image units: a method binds only those it uses; the numbers never change meaning.
#define IMAGE_COUNTER 0    // r32ui: fragments counted or held per pixel
#define IMAGE_SEMAPHORE 1  // r32ui: per-pixel spin-lock (0 = free)
#define IMAGE_WINDING 2    // r32i: winding index at the start of the kept span
#define IMAGE_OVERFLOW 3   // r32ui: 1 once a pixel lost fragments to a capacity limit
#define IMAGE_FRAGMENTS 4  // rg32ui 2D array: per-pixel fragment slots (k+, AB_FP)
#define IMAGE_HEAD 5       // r32ui: per-pixel head/offset into a node buffer (AB_LL, S-buffer, K+B-SB)
#define IMAGE_PEEL_DEPTH 6 // r32ui 2D array: peeling cursor, one field per layer (F2B, DUAL; peel_state.glsl)
#define IMAGE_WALK 7       // rgba32ui 2D array: trim walks carried between peeling passes (F2B, DUAL)
// Shader storage blocks (the scene data uses 1-4, see scene_data.glsl).
#define STORAGE_NODES 5    // uvec2 nodes[] of node-buffer methods
#define STORAGE_LINKS 6    // uint next[] of linked lists
#define STORAGE_SHARED_COUNTERS 7 // uint counters[] of the S-buffer's memory referencing; AB_LL's one node counter
#define STORAGE_DYNAMIC_STATE 8          // dynamic rules: per-pixel reference index and fragments behind
#define STORAGE_REFERENCE_BITS 9         // dynamic rules: the reference frame's characterization bit vectors
#define STORAGE_CHARACTERIZATION_BITS 10 // dynamic rules: the bit vectors a chain level writes
#define STORAGE_OBJECT_WINDINGS 11       // CSG, collisions: per-pixel per-object winding at the span start
