#version 430 core
// Walk pass of F2B, after every geometry pass (one invocation per pixel): feeds the key
// the front cursor found to the pixel's trim walk (common/trim_walk.glsl), moves the
// cursor on, and keeps peeling only while the walk has not found the trim fragment and
// the span holds unpeeled fragments. A pixel that stops sets its lock flag and discards;
// the pixels still peeling pass, and the occlusion query over this pass
// (GL_ANY_SAMPLES_PASSED) decides by conditional rendering whether another pass runs.
// No color is written (the capture state masks it).

#include "common/frame_counters.glsl"
#include "common/fragment_pack.glsl"
#include "common/static_rule.glsl"
#include "common/trim_walk.glsl"
#include "common/peel_key.glsl"
#include "common/peel_state.glsl"
#include "common/peel_walk_state.glsl"
#include "common/peel_cursor.glsl"

uniform bool u_firstPass; // the geometry pass only counted: start the walk

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    PeelWalk front = loadPeelWalk(pixel, WALK_FRONT);
    if (front.done)
        discard;
    if (u_firstPass)
        front.walk = beginTrimWalk(windingAtStart(pixel));
    else
        trimWalkStep(front.walk, takeFront(pixel));
    advanceFront(pixel, false);
    front.done = front.walk.found || peeledCount(pixel) >= spanCount(pixel);
    storePeelWalk(pixel, WALK_FRONT, front);
    if (front.done)
        discard;
}
