#version 430 core
// Memory referencing, step 2 (thesis 5.1.2, inverse mapping): the start of every hash
// group's memory from the final counter values. Invocation 0 sums G1 = {C(0) .. C(S/2)}
// forward, Cpr(i) = C(0) + .. + C(i-1); invocation 1 sums G2 = {C(S/2+1) .. C(S-1)}
// inverse, from the end, Cpr(i) = C(i+1) + .. + C(S-1). The two halves run at once,
// which is the factor of two the thesis gains; the total follows from both.

#define SHARED_COUNTERS_ACCESS coherent
#include "common/shared_counters.glsl"

layout(local_size_x = 2) in;

shared uint s_groupTotal[2];

void main()
{
    uint S = u_sharedCounterCount;
    uint lastForward = S / 2u;
    uint sum = 0u;
    if (gl_LocalInvocationID.x == 0u) {
        for (uint i = 0u; i <= lastForward; ++i) {
            sharedCounters[prefixIndex(i)] = sum;
            sum += sharedCounters[counterIndex(i)];
        }
    } else {
        for (uint i = S - 1u; i > lastForward; --i) {
            sharedCounters[prefixIndex(i)] = sum;
            sum += sharedCounters[counterIndex(i)];
        }
    }
    s_groupTotal[gl_LocalInvocationID.x] = sum;
    barrier();
    if (gl_LocalInvocationID.x == 0u)
        sharedCounters[totalIndex()] = s_groupTotal[0] + s_groupTotal[1];
}
