#version 430 core
// Geometry pass of front-to-back depth peeling (F2B; thesis 2.4.2), exact for coincident
// fragments (6.2.1) and with the lock flags of 8.1.2. Every unpeeled fragment of the kept
// span (key above the last one peeled, common/peel_key.glsl) offers its key to the
// pixel's front cursor; the walk pass after this one takes the smallest key and feeds it
// to the trim walk. Fragments of pixels that stopped peeling are discarded on arrival.
// The first pass also counts the exact winding index at the span start and the span's
// fragments; it peels nothing yet, it only finds the nearest depth.
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
    bool kept = u_firstPass ? countSpanFragment(pixel, v_viewPos, false) : clipKeeps(v_viewPos);
    if (!kept || peelLocked(pixel))
        discard;
    uvec2 key = peelKey(-v_viewPos.z, uint(gl_PrimitiveID), u_objectId, gl_FrontFacing);
    if (keyAbove(key, lowKey(pixel)))
        offerToFront(pixel, key);
    discard;
}
