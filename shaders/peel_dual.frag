#version 430 core
// Geometry pass of dual depth peeling (DUAL; thesis 2.4.2, made exact for coincident
// fragments like DUAL-2P of 6.2.2, with the lock flags of 8.1.2). Every unpeeled
// fragment of the kept span (key strictly between the last keys peeled from the front and
// from the back, common/peel_key.glsl) offers its key to both cursors: the min-max
// search of DUAL, on exact keys instead of a min-max depth buffer. The walk pass after
// this one takes the smallest and the largest key. Fragments of pixels that stopped
// peeling are discarded on arrival.
// The first pass also counts the exact winding index at the span start, the span's
// fragments and their facing sum (which gives the index at the span's far end); it peels
// nothing yet, it only finds the nearest and the farthest depth.
//
// No color is written and the shader ends in discard (docs/llvmpipe-notes.md, "Covered tiles").

#include "common/frame_counters.glsl"
#include "common/fragment_pack.glsl"
#include "common/clip.glsl"
#include "common/winding_count.glsl"
#include "common/peel_key.glsl"
#include "common/peel_state.glsl"
#include "common/peel_offer.glsl"

uniform bool u_firstPass;

in vec3 v_viewPos;

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    bool kept = u_firstPass ? countSpanFragment(pixel, v_viewPos, true) : clipKeeps(v_viewPos);
    if (!kept || peelLocked(pixel))
        discard;
    uvec2 key = peelKey(-v_viewPos.z, uint(gl_PrimitiveID), u_objectId, gl_FrontFacing);
    if (keyAbove(key, lowKey(pixel)) && keyAbove(highKey(pixel), key)) {
        offerToFront(pixel, key);
        offerToBack(pixel, key);
    }
    discard;
}
