// The trim decision as a walk over a pixel's fragments in depth order (thesis 8.1.2,
// "Clipping and Trimming with Static Rules"; CPU twin: core/trim/trim_walk). Buffer
// methods feed it the sorted fragments in one resolve pass; peeling methods feed it one
// fragment per pass and keep the walk in an image between passes. Later effects
// (capping, CSG, dynamic rules) extend this one walk instead of each method:
// - OBJECT_WINDINGS N (buffer methods): the walk also carries the winding index of each
//   object 0..N-1 and classifies by the CSG expression on their inside bits (Algorithm
//   8.14 for n operands, as a truth table) and flags colliding shown fragments;
// - COPLANAR_COUNT (buffer methods): the walk goes on over the fragments at the shown
//   fragment's depth and counts them;
// - capping reads the classification at the span start (g_startInterior, cap.glsl).
// - TRANSPARENCY (buffer methods): the walk goes on over every fragment of the span and
//   hands each to the X-ray compositing with its classification (transparency.glsl,
//   included by pixel_result.glsl); it stops once the compositing is done and the shown
//   fragment is known (walkTrimLayers + compositeXray in core/trim/).
// Needs fragment_pack.glsl and static_rule.glsl.

uniform bool u_trimEnabled;
uniform int u_rule;

#ifdef DYNAMIC_RULES
#include "common/dynamic_walk.glsl"
#else

#ifdef OBJECT_WINDINGS
#define OBJECT_WINDINGS_ACCESS readonly
#include "common/object_windings.glsl"

// Per-object walk state as globals: GLSL passes arrays by value, and a resolve runs one
// walk per invocation.
int g_objectWinding[OBJECT_WINDINGS];
bool g_collision = false;

uniform int u_objectRules[OBJECT_WINDINGS]; // TrimSettings::objectRule of each object
uniform bool u_csgEnabled;
uniform uint u_csgTable[8];                 // core/trim/csg_expression.h, CsgTruthTable
uniform bool u_highlightCollisions;

uint objectInsideBits()
{
    uint bits = 0u;
    for (int o = 0; o < OBJECT_WINDINGS; ++o)
        if (isInterior(u_objectRules[o], g_objectWinding[o]))
            bits |= 1u << uint(o);
    return bits;
}

bool walkInterior(int winding)
{
    if (!u_csgEnabled)
        return isInterior(u_rule, winding);
    uint bits = objectInsideBits();
    return ((u_csgTable[bits >> 5] >> (bits & 31u)) & 1u) != 0u;
}

// A fragment of object `o` collides: its own object overlaps itself there, or it lies
// inside another object.
bool fragmentCollides(uint o, int ownBefore, int ownAfter)
{
    if (max(abs(ownBefore), abs(ownAfter)) > 1)
        return true;
    for (int q = 0; q < OBJECT_WINDINGS; ++q)
        if (uint(q) != o && isInterior(u_objectRules[q], g_objectWinding[q]))
            return true;
    return false;
}
#else
bool walkInterior(int winding) { return isInterior(u_rule, winding); }
#endif

#ifdef COPLANAR_COUNT
int g_coplanar = 0;          // fragments at the shown fragment's depth
float g_groupDepth = -1.0;   // depth of the current run of equal-depth fragments
int g_groupCount = 0;        // fragments of that run fed so far
#endif

bool g_startInterior = false; // the classification at the span start (capping)

#ifdef TRANSPARENCY
// Defined in transparency.glsl (it needs the output and scene functions).
void beginXray(bool startInterior);
void xrayFragment(uvec2 fragment, bool boundary, bool interiorBefore, bool first);
bool xrayDone();
#endif

struct TrimWalk {
    int winding;  // index of the space in front of the next fragment
    bool found;   // the shown fragment is known
    uvec2 shown;  // the shown (trim) fragment once found
};

TrimWalk beginTrimWalk(int windingAtStart)
{
#ifdef OBJECT_WINDINGS
    uint base = objectWindingBase(ivec2(gl_FragCoord.xy));
    for (int o = 0; o < OBJECT_WINDINGS; ++o)
        g_objectWinding[o] = objectWindings[base + uint(o)];
#endif
    g_startInterior = u_trimEnabled && walkInterior(windingAtStart);
#ifdef TRANSPARENCY
    beginXray(g_startInterior);
#endif
    return TrimWalk(windingAtStart, false, uvec2(0u));
}

#ifdef TRANSPARENCY
// The walk of every fragment of the span (walkTrimLayers): the classification on both
// sides of each goes to the compositing; the first boundary is the shown fragment (with
// its highlights, as without transparency). Returns true once the compositing is done
// and the shown fragment (and, with COPLANAR_COUNT, the fragments at its depth) is known.
bool trimWalkStep(inout TrimWalk walk, uvec2 fragment)
{
#ifdef COPLANAR_COUNT
    float depth = fragmentDepth(fragment);
    if (depth != g_groupDepth) {
        g_groupDepth = depth;
        g_groupCount = 0;
    }
    ++g_groupCount;
    bool atShownDepth = walk.found && depth == fragmentDepth(walk.shown);
    if (atShownDepth)
        g_coplanar = g_groupCount;
    if (walk.found && xrayDone())
        return !atShownDepth;
#else
    if (walk.found && xrayDone())
        return true;
#endif
    int step = fragmentFrontFacing(fragment) ? 1 : -1;
    int after = walk.winding + step;
    bool interiorBefore = u_trimEnabled && walkInterior(walk.winding);
#ifdef OBJECT_WINDINGS
    uint o = fragmentObject(fragment);
    bool tracked = o < uint(OBJECT_WINDINGS);
    int ownBefore = tracked ? g_objectWinding[min(o, uint(OBJECT_WINDINGS - 1))] : 0; // no index formed out of range
    if (tracked)
        g_objectWinding[o] = ownBefore + step;
#endif
    bool boundary = !u_trimEnabled || interiorBefore != walkInterior(after);
    walk.winding = after;
    bool first = boundary && !walk.found;
    if (first) {
        walk.found = true;
        walk.shown = fragment;
#ifdef OBJECT_WINDINGS
        g_collision = u_highlightCollisions && tracked && fragmentCollides(o, ownBefore, ownBefore + step);
#endif
#ifdef COPLANAR_COUNT
        g_coplanar = g_groupCount;
#endif
    }
    xrayFragment(fragment, boundary, interiorBefore, first);
#ifdef COPLANAR_COUNT
    return false; // the next fragment tells whether the shown depth's group is complete
#else
    return walk.found && xrayDone();
#endif
}
#else

// Feeds the next fragment behind the previous one. Returns true once the walk is done:
// with trimming, at the first fragment whose two sides classify differently; without,
// at the first fragment (with COPLANAR_COUNT, after the fragments at its depth).
bool trimWalkStep(inout TrimWalk walk, uvec2 fragment)
{
#ifdef COPLANAR_COUNT
    float depth = fragmentDepth(fragment);
    if (depth != g_groupDepth) {
        g_groupDepth = depth;
        g_groupCount = 0;
    }
    ++g_groupCount;
    if (walk.found) {
        if (depth != fragmentDepth(walk.shown))
            return true;
        g_coplanar = g_groupCount;
        return false;
    }
#else
    if (walk.found)
        return true;
#endif
    int step = fragmentFrontFacing(fragment) ? 1 : -1;
    int after = walk.winding + step;
#ifdef OBJECT_WINDINGS
    uint o = fragmentObject(fragment);
    bool tracked = o < uint(OBJECT_WINDINGS);
    bool interiorBefore = walkInterior(walk.winding);
    int ownBefore = tracked ? g_objectWinding[min(o, uint(OBJECT_WINDINGS - 1))] : 0; // no index formed out of range
    if (tracked)
        g_objectWinding[o] = ownBefore + step;
    bool boundary = !u_trimEnabled || interiorBefore != walkInterior(after);
#else
    bool boundary = !u_trimEnabled || isTrimBoundary(u_rule, walk.winding, after);
#endif
    if (boundary) {
        walk.found = true;
        walk.shown = fragment;
#ifdef OBJECT_WINDINGS
        g_collision = u_highlightCollisions && tracked && fragmentCollides(o, ownBefore, ownBefore + step);
#endif
#ifdef COPLANAR_COUNT
        g_coplanar = g_groupCount;
        return false; // go on over the fragments at its depth
#else
        return true;
#endif
    }
    walk.winding = after;
    return false;
}

#endif // TRANSPARENCY

// Static walks are always decidable and leave nothing behind (the dynamic walk's
// versions of these record the characterization and report an overflowed reference).
bool trimWalkCertain(TrimWalk walk) { return true; }
void finishTrimWalk(TrimWalk walk, bool complete) {}
#endif

// The highlights of the shown fragment (trim_output.glsl): false / 0 where not tracked.
bool shownCollision()
{
#ifdef OBJECT_WINDINGS
    return g_collision;
#else
    return false;
#endif
}

int shownCoplanarCount()
{
#ifdef COPLANAR_COUNT
    return g_coplanar;
#else
    return 0;
#endif
}
