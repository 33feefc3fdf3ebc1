// Per-pixel state of the dynamic rules (thesis 8.1.2, Algorithms 8.12 and 8.13), kept in
// shader storage so it costs no image unit:
//   DynamicState: per pixel the reference frame's winding index at the span start and
//     the number of reference (low 16 bits) and current (high 16 bits) fragments behind it;
//   ReferenceBits: the reference frame's partition characterization bit vector PC^r;
//   CharacterizationBits: the one this frame writes when it is a chain level.
// A bit vector is CHARACTERIZATION_WORDS words plus a flag word (bit 0: overflowed).
// Frame classes travel as object ids: 0 both frames, 1 current only, 2 reference only.

#define CHARACTERIZATION_WORDS 8
#define CHARACTERIZATION_STRIDE 9
#define CHARACTERIZATION_LAYERS 256

layout(std430, binding = STORAGE_DYNAMIC_STATE) coherent buffer DynamicState {
    uint u_dynamicWidth; // pixels per row of every per-pixel array here
    uint u_dynamicPad;
    ivec2 dynamicPixels[];
};

bool objectInReferenceFrame(uint objectId) { return objectId != 1u; }
bool objectInCurrentFrame(uint objectId) { return objectId != 2u; }

uint dynamicPixelIndex(ivec2 pixel) { return uint(pixel.y) * u_dynamicWidth + uint(pixel.x); }

void countDynamicBehind(ivec2 pixel, uint objectId, int behind)
{
    uint index = dynamicPixelIndex(pixel);
    uint counts = 0u;
    if (objectInReferenceFrame(objectId)) {
        atomicAdd(dynamicPixels[index].x, behind);
        counts += 1u;
    }
    if (objectInCurrentFrame(objectId))
        counts += 1u << 16;
    atomicAdd(dynamicPixels[index].y, int(counts));
}
