// A stored fragment in two 32-bit words (the k+-buffer's RG32UI texel):
//   x: view depth (float bits; the distance along -z in view space, > 0)
//   y: primitive id (bits 0-23) | object id (bits 24-28) | front-facing (bit 29)
// Bits 30-31 are reserved for the frame class of the dynamic rules (thesis 8.1.2).
// Limits: 2^24 triangles per object, 32 objects (GpuScene checks them on upload).

uvec2 packFragment(float viewDepth, uint primitiveId, uint objectId, bool frontFacing)
{
    uint meta = (primitiveId & 0xFFFFFFu) | ((objectId & 31u) << 24) | (frontFacing ? (1u << 29) : 0u);
    return uvec2(floatBitsToUint(viewDepth), meta);
}

float fragmentDepth(uvec2 f) { return uintBitsToFloat(f.x); }
uint fragmentPrimitive(uvec2 f) { return f.y & 0xFFFFFFu; }
uint fragmentObject(uvec2 f) { return (f.y >> 24) & 31u; }
bool fragmentFrontFacing(uvec2 f) { return ((f.y >> 29) & 1u) != 0u; }

// The walk order of the CPU reference (core/trim/ray_hit.h, walkOrder): by view depth,
// ties (coincident surfaces) by object id, then primitive id, so every backend and every
// frame resolves them alike (thesis chapter 6). The facing bit and the dynamic rules'
// bits 30-31 take no part.
uint fragmentOrderKey(uvec2 f) { return f.y & 0x1FFFFFFFu; }

// True when `a` comes after `b` in the walk order.
bool fragmentAfter(uvec2 a, uvec2 b)
{
    float da = fragmentDepth(a);
    float db = fragmentDepth(b);
    return da > db || (da == db && fragmentOrderKey(a) > fragmentOrderKey(b));
}
