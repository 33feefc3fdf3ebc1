// The end of every buffer method's resolve: counts an overflowed pixel, then shows the
// walk's answer when it is `certain` (provably what an exact walk over all fragments
// gives: the trim fragment, or nothing), and otherwise paints the pixel unresolved
// (counted, magenta) — never silently wrong. A pixel that lost fragments is certain only
// when the walk found its trim fragment in front of every lost one; a pixel whose long
// list could not be sorted within the loop budget is never certain.
// Needs frame_counters.glsl, trim_walk.glsl and trim_output.glsl.

void emitWalkResult(TrimWalk walk, bool certain, int windingAtStart, bool overflowed)
{
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
