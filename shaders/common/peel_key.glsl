// The total order in which the depth-peeling methods (F2B, DUAL) take a pixel's
// fragments, and the fragment a peeled key stands for.
//
// A key is (view depth bits, order word). View depths of kept fragments are positive
// floats, whose bit patterns order like the values. The order word sorts fragments at
// exactly the same depth by object id, then primitive id (the CPU reference's walkOrder,
// core/trim/ray_hit.h) and carries the facing in its lowest bit:
//   bits 25-29 object id | bits 1-24 primitive id | bit 0 front-facing.
// A triangle covers a pixel centre at most once, so two fragments of one pixel never
// share a key: "the smallest key above the last one peeled" names exactly one fragment,
// and peeling by it takes every fragment once, also where coincident triangles tie in
// depth (the coplanarity problem of thesis 6.1, which classic F2B gets wrong).
// Needs fragment_pack.glsl.

uint peelOrderWord(uint objectId, uint primitiveId, bool frontFacing)
{
    return ((objectId & 31u) << 25) | ((primitiveId & 0xFFFFFFu) << 1) | (frontFacing ? 1u : 0u);
}

uvec2 peelKey(float viewDepth, uint primitiveId, uint objectId, bool frontFacing)
{
    return uvec2(floatBitsToUint(viewDepth), peelOrderWord(objectId, primitiveId, frontFacing));
}

// key > bound in the peeling order.
bool keyAbove(uvec2 key, uvec2 bound)
{
    return key.x > bound.x || (key.x == bound.x && key.y > bound.y);
}

// The stored-fragment form (fragment_pack.glsl) of a key, for the trim walk and output.
uvec2 keyFragment(uvec2 key)
{
    return packFragment(uintBitsToFloat(key.x), (key.y >> 1) & 0xFFFFFFu, key.y >> 25, (key.y & 1u) != 0u);
}
