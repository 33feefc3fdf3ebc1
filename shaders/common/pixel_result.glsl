// The end of every buffer method's resolve: counts an overflowed pixel, then shows the
// walk's answer when it is `certain` (provably what an exact walk over all fragments
// gives: the trim fragment, or nothing), and otherwise paints the pixel unresolved
// (counted, magenta) — never silently wrong. A pixel that lost fragments is certain only
// when the walk found its trim fragment in front of every lost one; a pixel whose long
// list could not be sorted within the loop budget is never certain.
// With CAPPING the cap comes first (cap.glsl). Needs frame_counters.glsl, trim_walk.glsl and
// trim_output.glsl.

#ifdef CAPPING
#include "common/cap.glsl"
#endif

void emitWalkResult(TrimWalk walk, bool certain, int windingAtStart, bool overflowed)
{
#ifdef CAPPING
    // A cap depends only on the exactly counted start of the span, never on storage.
    if (emitCapIfShown(g_startInterior, windingAtStart, overflowed)) {
        if (overflowed)
            atomicCounterIncrement(u_overflowPixels);
        return;
    }
#endif
    finishTrimWalk(walk, certain && !overflowed);
    certain = certain && trimWalkCertain(walk);
    if (overflowed)
        atomicCounterIncrement(u_overflowPixels);
    if (!certain) {
        atomicCounterIncrement(u_unresolvedPixels);
        emitEmptyPixel(windingAtStart, overflowed, true);
    } else if (walk.found) {
        emitShownPixel(walk.shown, windingAtStart, overflowed);
    } else {
        emitEmptyPixel(windingAtStart, overflowed, false);
    }
}
