// The walk-pass side of the depth-peeling cursor (peel_state.glsl explains the fields):
// take the key the last geometry pass found, move the cursor on, reset the accumulators.
// Needs frame_counters.glsl, peel_key.glsl, peel_state.glsl, peel_walk_state.glsl.

void notePeeled(ivec2 pixel)
{
    imageStore(u_counter, pixel, uvec4(peeledCount(pixel) + 1u));
    atomicCounterIncrement(u_fragmentsStored);
}

// The smallest unpeeled key, as a fragment; it becomes the lower bound of the unpeeled keys.
uvec2 takeFront(ivec2 pixel)
{
    uvec2 key = uvec2(peelLoad(pixel, PEEL_FRONT_DEPTH), peelLoad(pixel, PEEL_FRONT_ORDER));
    peelStore(pixel, PEEL_LOW_DEPTH, key.x);
    peelStore(pixel, PEEL_LOW_ORDER, key.y);
    notePeeled(pixel);
    return keyFragment(key);
}

// The largest unpeeled key, as a fragment; it becomes the upper bound of the unpeeled keys.
uvec2 takeBack(ivec2 pixel)
{
    uvec2 key = uvec2(peelLoad(pixel, PEEL_BACK_DEPTH), peelLoad(pixel, PEEL_BACK_ORDER));
    peelStore(pixel, PEEL_HIGH_DEPTH, key.x);
    peelStore(pixel, PEEL_HIGH_ORDER, key.y);
    notePeeled(pixel);
    return keyFragment(key);
}

// After the front key was taken: the cursor stays at its depth while another unpeeled key
// lies there (its tie count included the one taken), else it moves to the next depth. On
// the first pass nothing was counted at depth 0, so it moves to the nearest depth.
// `stay`: keep the depth regardless (DUAL, when every unpeeled key has one depth).
void advanceFront(ivec2 pixel, bool stay)
{
    if (!stay && peelLoad(pixel, PEEL_FRONT_TIES) < 2u)
        peelStore(pixel, PEEL_FRONT_DEPTH, peelLoad(pixel, PEEL_NEXT_FRONT));
    peelStore(pixel, PEEL_NEXT_FRONT, peelInitialValue(PEEL_NEXT_FRONT));
    peelStore(pixel, PEEL_FRONT_ORDER, peelInitialValue(PEEL_FRONT_ORDER));
    peelStore(pixel, PEEL_FRONT_TIES, 0u);
}

// The mirror image of advanceFront for the back cursor.
void advanceBack(ivec2 pixel, bool stay)
{
    if (!stay && peelLoad(pixel, PEEL_BACK_TIES) < 2u)
        peelStore(pixel, PEEL_BACK_DEPTH, peelLoad(pixel, PEEL_NEXT_BACK));
    peelStore(pixel, PEEL_NEXT_BACK, peelInitialValue(PEEL_NEXT_BACK));
    peelStore(pixel, PEEL_BACK_ORDER, peelInitialValue(PEEL_BACK_ORDER));
    peelStore(pixel, PEEL_BACK_TIES, 0u);
}
