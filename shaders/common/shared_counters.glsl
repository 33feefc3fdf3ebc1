// The S shared counters of the S-buffer's memory referencing (thesis 5.1.2), one shader
// storage array (render/mfr/memory_referencing.h allocates it):
//   [0, S):   C(i), the fragments of the pixels hashed to counter i (equation 5.1)
//   [S, 2S):  Cpr(i), the start of group i's memory: a forward prefix sum over
//             G1 = {C(0) .. C(S/2)}, an inverse one (from the end) over G2 = the rest
//   [2S]:     the total number of fragments (nodes) of the frame
// The includer defines SHARED_COUNTERS_ACCESS.

layout(std430, binding = STORAGE_SHARED_COUNTERS) SHARED_COUNTERS_ACCESS buffer SharedCounters
{
    uint sharedCounters[];
};

uniform uint u_sharedCounterCount; // S >= 1

uint counterIndex(uint i) { return i; }
uint prefixIndex(uint i) { return u_sharedCounterCount + i; }
uint totalIndex() { return 2u * u_sharedCounterCount; }

// G1 holds counters 0 .. floor(S/2); G2 the rest (empty for S <= 2).
bool inForwardGroup(uint i) { return i <= u_sharedCounterCount / 2u; }

// H(p) = (p.x + width * p.y) mod S.
uint pixelHash(ivec2 pixel, ivec2 size) { return (uint(pixel.x) + uint(size.x) * uint(pixel.y)) % u_sharedCounterCount; }
