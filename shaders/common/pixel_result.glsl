// The end of every buffer method's resolve: counts an overflowed pixel, then shows the
// walk's answer when it is `certain` (provably what an exact walk over all fragments
// gives: the trim fragment, or nothing), and otherwise paints the pixel unresolved
// (counted, magenta) — never silently wrong. A pixel that lost fragments is certain only
// when the walk found its trim fragment in front of every lost one; a pixel whose long
// list could not be sorted within the loop budget is never certain.
// With CAPPING the cap comes first (cap.glsl). With TRANSPARENCY the color is the X-ray
// composite (transparency.glsl); the id texel stays as without. Needs frame_counters.glsl, trim_walk.glsl and
// trim_output.glsl.

// clip.glsl first: cap.glsl and transparency.glsl both need it, and each file is
// expanded once only, at its first #include.
#include "common/clip.glsl"
#ifdef CAPPING
#include "common/cap.glsl"
#endif
#ifdef TRANSPARENCY
#include "common/transparency.glsl"
#endif

void emitWalkResult(TrimWalk walk, bool certain, int windingAtStart, bool overflowed)
{
#ifdef CAPPING
    // A cap depends only on the exactly counted start of the span, never on storage.
    if (emitCapIfShown(g_startInterior, windingAtStart, overflowed)) {
        if (overflowed)
            atomicCounterIncrement(u_overflowPixels);
#ifdef TRANSPARENCY
        o_color = vec4(xrayPixelColor(o_color.rgb), 1.0);
#endif
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
#ifdef TRANSPARENCY
    // An uncertain pixel composites what it has (its shown fragment without highlights);
    // its id texel still says unresolved.
    float cosine;
    vec3 shown = !walk.found ? vec3(0.0) : (certain ? o_color.rgb : xrayShade(walk.shown, cosine));
    o_color = vec4(xrayPixelColor(shown), 1.0);
#endif
}
