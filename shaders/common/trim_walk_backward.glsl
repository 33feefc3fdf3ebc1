// The trim walk of trim_walk.glsl run from the far end of the kept span towards its start,
// for dual depth peeling's back layers. Here walk.winding is the index of the space
// *behind* the next fragment; the walk starts from the index just behind the span's last
// fragment, which is exact because the span's facing sum is counted exactly (w_end =
// w_start + sum of (front-facing ? +1 : -1)).
// A boundary found from the back is only a candidate: the shown fragment is the *first*
// boundary from the front, so each boundary found replaces the previous (it is nearer)
// and never ends this walk. Once the front and back walks have met, the nearest candidate
// is the answer if the front walk found none (peel_dual_walk.frag).
// Needs trim_walk.glsl.

void trimWalkStepBackward(inout TrimWalk walk, uvec2 fragment)
{
    int before = walk.winding - (fragmentFrontFacing(fragment) ? 1 : -1);
    if (!u_trimEnabled || isTrimBoundary(u_rule, before, walk.winding)) {
        walk.found = true;
        walk.shown = fragment;
    }
    walk.winding = before;
}
