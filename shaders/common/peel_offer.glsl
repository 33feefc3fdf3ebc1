// The geometry-pass side of the depth-peeling cursor (peel_state.glsl explains the
// fields): every unpeeled fragment offers its key to the stages that still need it.
// Needs frame_counters.glsl, clip.glsl, winding_count.glsl, peel_key.glsl, peel_state.glsl.

// First pass only: counts the winding index at the span start (exact, from the far side)
// and the fragments of the span; with `turn`, also their facing sum (DUAL's far end).
// Returns whether the fragment is in the kept span.
bool countSpanFragment(ivec2 pixel, vec3 viewPos, bool turn)
{
    if (!countWinding(pixel, viewPos))
        return false;
    atomicCounterIncrement(u_fragmentsInSpan);
    imageAtomicAdd(u_peel, ivec3(pixel, PEEL_SPAN_COUNT), 1u);
    if (turn)
        imageAtomicAdd(u_peel, ivec3(pixel, PEEL_SPAN_TURN), gl_FrontFacing ? 1u : 0xFFFFFFFFu);
    return true;
}

// The front stages: at the cursor's depth the fragment competes for the smallest order
// word (and is counted); beyond it, for the next depth. Unpeeled keys are never in front
// of the cursor's depth, which is their minimum.
void offerToFront(ivec2 pixel, uvec2 key)
{
    uint frontDepth = peelLoad(pixel, PEEL_FRONT_DEPTH);
    if (key.x == frontDepth) {
        imageAtomicMin(u_peel, ivec3(pixel, PEEL_FRONT_ORDER), key.y);
        imageAtomicAdd(u_peel, ivec3(pixel, PEEL_FRONT_TIES), 1u);
    } else if (key.x > frontDepth) {
        imageAtomicMin(u_peel, ivec3(pixel, PEEL_NEXT_FRONT), key.x);
    }
}

// The back stages, mirrored: the largest order word at the cursor's depth, the largest
// depth in front of it.
void offerToBack(ivec2 pixel, uvec2 key)
{
    uint backDepth = peelLoad(pixel, PEEL_BACK_DEPTH);
    if (key.x == backDepth) {
        imageAtomicMax(u_peel, ivec3(pixel, PEEL_BACK_ORDER), key.y);
        imageAtomicAdd(u_peel, ivec3(pixel, PEEL_BACK_TIES), 1u);
    } else if (key.x < backDepth) {
        imageAtomicMax(u_peel, ivec3(pixel, PEEL_NEXT_BACK), key.x);
    }
}
