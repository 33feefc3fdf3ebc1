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
