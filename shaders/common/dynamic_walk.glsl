// The trim walk under a dynamic rule (thesis Algorithms 8.11–8.13): the GLSL twin of
// core/trim/dynamic_walk.cpp — keep the two identical. Included by trim_walk.glsl when
// DYNAMIC_RULES is defined, with the same functions as the static walk, so every buffer
// method's resolve runs it unchanged. With DYNAMIC_CHARACTERIZE the walk visits every
// fragment and records the class of each current-frame interval instead of stopping at
// the trim: the characterization the next set takes as its reference.
// Needs fragment_pack.glsl and static_rule.glsl; u_rule is the base mesh's static rule.

#include "common/dynamic_state.glsl"

uniform int u_dynamicRule;      // DynamicRule: 0 additive, 1 subtractive, 2 intersection, 3/4 confluent
uniform bool u_referenceIsBase; // the reference is the base mesh: classify it by u_rule

layout(std430, binding = STORAGE_REFERENCE_BITS) readonly buffer ReferenceBits {
    uint referenceBits[];
};
#ifdef DYNAMIC_CHARACTERIZE
layout(std430, binding = STORAGE_CHARACTERIZATION_BITS) writeonly buffer CharacterizationBits {
    uint characterizationBits[];
};
#endif

struct TrimWalk {
    int winding;  // current index w_c in front of the next fragment (p^c.index)
    bool found;
    uvec2 shown;
    int referenceIndex;  // p^r.index
    int referenceBehind; // reference fragments behind the position (interval of PC^r)
    int currentBehind;   // current fragments behind the position
    bool referenceInterior;
    bool currentInterior;
    bool unresolved; // PC^r could not hold this pixel's reference intervals
#ifdef DYNAMIC_CHARACTERIZE
    uint bits[CHARACTERIZATION_WORDS];
    bool overflowed;
#endif
};

bool dynamicInterior(int rule, int wReference, int wCurrent, bool interiorInReference)
{
    bool changed = wReference != wCurrent;
    if (rule == 0)
        return interiorInReference || changed;
    if (rule == 1)
        return interiorInReference && !changed;
    if (rule == 2)
        return interiorInReference && changed;
    return changed ? wCurrent > wReference : interiorInReference;
}

bool referenceClass(inout TrimWalk walk)
{
    if (u_referenceIsBase)
        return isInterior(u_rule, walk.referenceIndex);
    int n = walk.referenceBehind;
    // Behind every reference fragment: the unbounded interval, outside under every rule
    // (both indices are 0 there, so each rule keeps the class before it, back to the
    // static rule's class of w = 0). It is known even where the characterization
    // overflowed, so an emptied pixel forgets an overflow of earlier frames.
    if (n == 0)
        return false;
    uint base = dynamicPixelIndex(ivec2(gl_FragCoord.xy)) * uint(CHARACTERIZATION_STRIDE);
    if ((referenceBits[base + uint(CHARACTERIZATION_WORDS)] & 1u) != 0u || n >= CHARACTERIZATION_LAYERS)
        walk.unresolved = true;
    if (n < 0 || n >= CHARACTERIZATION_LAYERS)
        return false;
    return ((referenceBits[base + uint(n >> 5)] >> uint(n & 31)) & 1u) != 0u;
}

#ifdef DYNAMIC_CHARACTERIZE
void recordInterval(inout TrimWalk walk)
{
    int n = walk.currentBehind;
    if (n < 0 || n >= CHARACTERIZATION_LAYERS) {
        walk.overflowed = true;
        return;
    }
    uint mask = 1u << uint(n & 31);
    if (walk.currentInterior)
        walk.bits[n >> 5] |= mask;
    else
        walk.bits[n >> 5] &= ~mask;
}
#endif

TrimWalk beginTrimWalk(int windingAtStart)
{
    ivec2 counts = dynamicPixels[dynamicPixelIndex(ivec2(gl_FragCoord.xy))];
    TrimWalk walk;
    walk.winding = windingAtStart;
    walk.found = false;
    walk.shown = uvec2(0u);
    walk.referenceIndex = counts.x;
    walk.referenceBehind = counts.y & 0xFFFF;
    walk.currentBehind = (counts.y >> 16) & 0xFFFF;
    walk.unresolved = false;
    walk.referenceInterior = referenceClass(walk);
    walk.currentInterior = dynamicInterior(u_dynamicRule, walk.referenceIndex, walk.winding, walk.referenceInterior);
#ifdef DYNAMIC_CHARACTERIZE
    for (int i = 0; i < CHARACTERIZATION_WORDS; ++i)
        walk.bits[i] = 0u;
    walk.overflowed = false;
    recordInterval(walk);
#endif
    return walk;
}

// Feeds the next fragment behind the previous one; true once the walk is done.
bool trimWalkStep(inout TrimWalk walk, uvec2 fragment)
{
    if (walk.found)
        return true;
    uint objectId = fragmentObject(fragment);
    int crossing = fragmentFrontFacing(fragment) ? 1 : -1;
    if (objectInReferenceFrame(objectId)) {
        walk.referenceIndex += crossing;
        walk.referenceBehind -= 1;
        walk.referenceInterior = referenceClass(walk);
    }
    if (!objectInCurrentFrame(objectId))
        return false;
    walk.winding += crossing;
    walk.currentBehind -= 1;
    bool before = walk.currentInterior;
    walk.currentInterior = dynamicInterior(u_dynamicRule, walk.referenceIndex, walk.winding, walk.referenceInterior);
#ifdef DYNAMIC_CHARACTERIZE
    recordInterval(walk);
    return false;
#else
    if (!u_trimEnabled || walk.currentInterior != before) {
        walk.found = true;
        walk.shown = fragment;
        return true;
    }
    return false;
#endif
}

bool trimWalkCertain(TrimWalk walk) { return !walk.unresolved; }

// `complete`: the walk saw every fragment of the pixel.
void finishTrimWalk(TrimWalk walk, bool complete)
{
#ifdef DYNAMIC_CHARACTERIZE
    uint base = dynamicPixelIndex(ivec2(gl_FragCoord.xy)) * uint(CHARACTERIZATION_STRIDE);
    for (int i = 0; i < CHARACTERIZATION_WORDS; ++i)
        characterizationBits[base + uint(i)] = walk.bits[i];
    bool overflowed = walk.overflowed || walk.unresolved || !complete;
    characterizationBits[base + uint(CHARACTERIZATION_WORDS)] = overflowed ? 1u : 0u;
#endif
}
