#version 430 core
// Walk pass of DUAL, after every geometry pass (one invocation per pixel).
//
// How the back layers serve the trim walk: the shown fragment is the first one, from the
// span start, whose two sides classify differently. The winding index is known exactly at
// both ends of the span (at the start from the far-side count, at the end as the start
// plus the span's facing sum), and each fragment's sides differ by its facing, so the
// walk can run from either end (common/trim_walk_backward.glsl). The front walk ends the
// pixel as soon as it finds a boundary: that is the answer whatever lies behind. The back
// walk cannot end anything, since an unpeeled fragment between the two cursors may be an
// earlier boundary; it keeps the nearest boundary it has seen. When the two walks meet
// (every fragment of the span peeled) without a front boundary, the nearest back boundary
// is the first boundary of the span, or there is none. So DUAL halves the passes where
// the trim lies deep or is absent, and equals F2B where the trim is near the front.
// At the meeting point both walks must carry the same index; a pixel where they do not
// is flagged unresolved rather than shown (a lost or repeated fragment would cause it).
//
// A pixel that stops sets its lock flag and discards; the pixels still peeling pass, and
// the occlusion query over this pass decides by conditional rendering whether another
// pass runs. No color is written (the capture state masks it).

#include "common/frame_counters.glsl"
#include "common/fragment_pack.glsl"
#include "common/static_rule.glsl"
#include "common/trim_walk.glsl"
#include "common/trim_walk_backward.glsl"
#include "common/peel_key.glsl"
#include "common/peel_state.glsl"
#include "common/peel_walk_state.glsl"
#include "common/peel_cursor.glsl"

uniform bool u_firstPass; // the geometry pass only counted: start both walks

void beginWalks(ivec2 pixel, inout PeelWalk front, inout PeelWalk back)
{
    int start = windingAtStart(pixel);
    front.walk = beginTrimWalk(start);
    back.walk = beginTrimWalk(start + int(peelLoad(pixel, PEEL_SPAN_TURN)));
}

// Feeds the smallest unpeeled key to the front walk and the largest to the back walk;
// with a single unpeeled fragment the two are the same, and only the front walk gets it.
void peelBothEnds(ivec2 pixel, inout PeelWalk front, inout PeelWalk back)
{
    bool single = spanCount(pixel) - peeledCount(pixel) < 2u;
    trimWalkStep(front.walk, takeFront(pixel));
    if (!single)
        trimWalkStepBackward(back.walk, takeBack(pixel));
}

// The walks met and the front walk found no boundary: the back walk's nearest one is
// the answer (or none).
void takeBackAnswer(inout PeelWalk front, PeelWalk back)
{
    if (front.walk.winding != back.walk.winding) {
        front.inconsistent = true;
    } else if (back.walk.found) {
        front.walk.found = true;
        front.walk.shown = back.walk.shown;
    }
}

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    PeelWalk front = loadPeelWalk(pixel, WALK_FRONT);
    if (front.done)
        discard;
    PeelWalk back = loadPeelWalk(pixel, WALK_BACK);
    if (u_firstPass)
        beginWalks(pixel, front, back);
    else
        peelBothEnds(pixel, front, back);
    // Both cursors keep their depth while every unpeeled key lies at that one depth.
    bool oneDepth = peelLoad(pixel, PEEL_FRONT_DEPTH) == peelLoad(pixel, PEEL_BACK_DEPTH);
    advanceFront(pixel, oneDepth);
    advanceBack(pixel, oneDepth);
    bool met = peeledCount(pixel) >= spanCount(pixel);
    if (met && !front.walk.found)
        takeBackAnswer(front, back);
    front.done = front.walk.found || met;
    storePeelWalk(pixel, WALK_FRONT, front);
    storePeelWalk(pixel, WALK_BACK, back);
    if (front.done)
        discard;
}
