// Per-pixel state the depth-peeling methods carry between passes (C++ side:
// render/mfr/peeling_state.h; keep the layer numbers identical).
//
// IMAGE_PEEL_DEPTH is an r32ui array with one field per layer (image atomics need
// single-channel images). The unpeeled fragments of a pixel are the keys (peel_key.glsl)
// strictly between LOW and HIGH. Finding the smallest of them takes two stages, depth
// then order word, and the passes are pipelined: the geometry pass that completes the
// order stage for the depth found in the previous pass also runs the depth stage for the
// next one (the id ranges of thesis 6.2.1, F2B-2P, with a count per depth).
//   LOW_DEPTH, LOW_ORDER    the last key peeled from the front; (0, 0) before the first
//   FRONT_DEPTH             depth of the smallest unpeeled key; 0 before the first pass
//   NEXT_FRONT   (atomic)   smallest unpeeled depth beyond FRONT_DEPTH
//   FRONT_ORDER  (atomic)   smallest order word among the unpeeled keys at FRONT_DEPTH
//   FRONT_TIES   (atomic)   number of unpeeled keys at FRONT_DEPTH
//   SPAN_COUNT   (atomic)   fragments in the kept span (first pass)
// Dual depth peeling adds the mirror image for the largest unpeeled key:
//   HIGH_DEPTH, HIGH_ORDER  the last key peeled from the back; all ones before the first
//   BACK_DEPTH              depth of the largest unpeeled key; all ones before the first pass
//   NEXT_BACK    (atomic)   largest unpeeled depth in front of BACK_DEPTH
//   BACK_ORDER   (atomic)   largest order word among the unpeeled keys at BACK_DEPTH
//   BACK_TIES    (atomic)   number of unpeeled keys at BACK_DEPTH
//   SPAN_TURN    (atomic)   sum over the span of (front-facing ? +1 : -1), as int bits
// The walk pass reads the atomic fields, moves the cursor and resets them.
//
// IMAGE_WALK is an rgba32ui array, one trim walk per layer (peel_walk_state.glsl): the
// walk from the front (layer 0) and, for DUAL, the walk from the back (layer 1).

const int PEEL_LOW_DEPTH = 0;
const int PEEL_LOW_ORDER = 1;
const int PEEL_FRONT_DEPTH = 2;
const int PEEL_NEXT_FRONT = 3;
const int PEEL_FRONT_ORDER = 4;
const int PEEL_FRONT_TIES = 5;
const int PEEL_SPAN_COUNT = 6;
const int PEEL_LAYERS_F2B = 7;
const int PEEL_HIGH_DEPTH = 7;
const int PEEL_HIGH_ORDER = 8;
const int PEEL_BACK_DEPTH = 9;
const int PEEL_NEXT_BACK = 10;
const int PEEL_BACK_ORDER = 11;
const int PEEL_BACK_TIES = 12;
const int PEEL_SPAN_TURN = 13;
const int PEEL_LAYERS_DUAL = 14;

const int WALK_FRONT = 0;
const int WALK_BACK = 1;
// Flags of a walk layer's y component.
const uint WALK_DONE = 1u;         // the pixel stopped peeling: the lock flag of thesis 8.1.2
const uint WALK_FOUND = 2u;        // the walk found its trim fragment (the back walk: a candidate)
const uint WALK_INCONSISTENT = 4u; // DUAL: the walks met with different winding indices

layout(binding = IMAGE_PEEL_DEPTH, r32ui) uniform coherent uimage2DArray u_peel;
layout(binding = IMAGE_WALK, rgba32ui) uniform coherent uimage2DArray u_walk;

uint peelLoad(ivec2 pixel, int field) { return imageLoad(u_peel, ivec3(pixel, field)).r; }
void peelStore(ivec2 pixel, int field, uint value) { imageStore(u_peel, ivec3(pixel, field), uvec4(value)); }

uvec2 lowKey(ivec2 pixel) { return uvec2(peelLoad(pixel, PEEL_LOW_DEPTH), peelLoad(pixel, PEEL_LOW_ORDER)); }
uvec2 highKey(ivec2 pixel) { return uvec2(peelLoad(pixel, PEEL_HIGH_DEPTH), peelLoad(pixel, PEEL_HIGH_ORDER)); }

// True once the pixel stopped peeling: its fragments are discarded on arrival.
bool peelLocked(ivec2 pixel)
{
    return (imageLoad(u_walk, ivec3(pixel, WALK_FRONT)).y & WALK_DONE) != 0u;
}

// The value a field holds before a frame's first pass.
uint peelInitialValue(int field)
{
    bool allOnes = field == PEEL_NEXT_FRONT || field == PEEL_FRONT_ORDER || field == PEEL_HIGH_DEPTH ||
                   field == PEEL_HIGH_ORDER || field == PEEL_BACK_DEPTH;
    return allOnes ? 0xFFFFFFFFu : 0u;
}
