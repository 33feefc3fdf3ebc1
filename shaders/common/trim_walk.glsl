// The trim decision as a walk over a pixel's fragments in depth order (thesis 8.1.2,
// "Clipping and Trimming with Static Rules"; CPU twin: core/trim/trim_walk). Buffer
// methods feed it the sorted fragments in one resolve pass; peeling methods feed it one
// fragment per pass and keep the walk in an image between passes. Later effects
// (capping, CSG, dynamic rules) extend this one walk instead of each method.
// Needs fragment_pack.glsl and static_rule.glsl.

uniform bool u_trimEnabled;
uniform int u_rule;

#ifdef DYNAMIC_RULES
#include "common/dynamic_walk.glsl"
#else

struct TrimWalk {
    int winding;  // index of the space in front of the next fragment
    bool found;   // the shown fragment is known
    uvec2 shown;  // the shown (trim) fragment once found
};

TrimWalk beginTrimWalk(int windingAtStart)
{
    return TrimWalk(windingAtStart, false, uvec2(0u));
}

// Feeds the next fragment behind the previous one. Returns true once the walk is done:
// with trimming, at the first fragment whose two sides classify differently; without,
// at the first fragment.
bool trimWalkStep(inout TrimWalk walk, uvec2 fragment)
{
    if (walk.found)
        return true;
    int after = walk.winding + (fragmentFrontFacing(fragment) ? 1 : -1);
    if (!u_trimEnabled || isTrimBoundary(u_rule, walk.winding, after)) {
        walk.found = true;
        walk.shown = fragment;
        return true;
    }
    walk.winding = after;
    return false;
}

// Static walks are always decidable and leave nothing behind (the dynamic walk's
// versions of these record the characterization and report an overflowed reference).
bool trimWalkCertain(TrimWalk walk) { return true; }
void finishTrimWalk(TrimWalk walk, bool complete) {}
#endif
