#include "core/trim/dynamic_walk.h"

#include "core/trim/dynamic_frame_scene.h"

namespace trimlab {

namespace {

/// The registers of Algorithm 8.13 (p^r.index, p^c.index, p^r.class, p^c.class) plus the
/// interval counters that index the characterization bit vectors.
struct DynamicRegisters {
    int referenceIndex = 0;
    int currentIndex = 0;
    int referenceBehind = 0; ///< reference hits behind the current position
    int currentBehind = 0;   ///< current hits behind the current position
    bool referenceInterior = false;
    bool currentInterior = false;
    bool unresolved = false;
};

int crossing(const RayHit& hit)
{
    return hit.facing > 0 ? 1 : -1;
}

bool referenceClass(const ReferenceClassification& reference, const DynamicRegisters& r, bool& unresolved)
{
    if (!reference.characterization)
        return isInterior(reference.staticRule, r.referenceIndex);
    // Behind every reference hit: the unbounded interval, outside under every rule (both
    // indices are 0 there, so each rule keeps the class before it, back to the static
    // rule's class of w = 0). It is known even where the characterization overflowed.
    if (r.referenceBehind == 0)
        return false;
    if (reference.characterization->overflowed || r.referenceBehind >= PartitionCharacterization::kLayers)
        unresolved = true;
    return reference.characterization->interior(r.referenceBehind);
}

/// The registers at a point with hits [first, end) behind it (Algorithms 8.11/8.12).
DynamicRegisters registersAt(std::span<const RayHit> hits, std::size_t first, DynamicRule rule,
                             const ReferenceClassification& reference)
{
    DynamicRegisters r;
    for (std::size_t i = first; i < hits.size(); ++i) {
        const FrameClass c = frameClassOfObject(hits[i].objectId);
        const int behind = -crossing(hits[i]); // from the far side: back-facing adds one
        if (inReference(c)) {
            r.referenceIndex += behind;
            ++r.referenceBehind;
        }
        if (inCurrent(c)) {
            r.currentIndex += behind;
            ++r.currentBehind;
        }
    }
    r.referenceInterior = referenceClass(reference, r, r.unresolved);
    r.currentInterior = dynamicInterior(rule, r.referenceIndex, r.currentIndex, r.referenceInterior);
    return r;
}

/// Moves the registers across `hit` (front to back). Returns whether the current class
/// changed there; `crossedCurrent` says whether the hit belongs to the current frame.
bool step(DynamicRegisters& r, const RayHit& hit, DynamicRule rule, const ReferenceClassification& reference,
          bool& crossedCurrent)
{
    const FrameClass c = frameClassOfObject(hit.objectId);
    if (inReference(c)) {
        r.referenceIndex += crossing(hit);
        --r.referenceBehind;
        r.referenceInterior = referenceClass(reference, r, r.unresolved);
    }
    crossedCurrent = inCurrent(c);
    if (!crossedCurrent)
        return false;
    r.currentIndex += crossing(hit);
    --r.currentBehind;
    const bool before = r.currentInterior;
    r.currentInterior = dynamicInterior(rule, r.referenceIndex, r.currentIndex, r.referenceInterior);
    return r.currentInterior != before;
}

} // namespace

DynamicWalkResult walkDynamicRay(std::span<const RayHit> sortedHits, const KeptSpan& span, const TrimSettings& settings,
                                 DynamicRule rule, const ReferenceClassification& reference)
{
    DynamicWalkResult result;
    TrimWalk& walk = result.walk;
    if (span.empty)
        return result;
    const std::size_t n = sortedHits.size();
    while (walk.walkBegin < n && sortedHits[walk.walkBegin].t <= span.tStart)
        ++walk.walkBegin;
    walk.walkEnd = walk.walkBegin;
    while (walk.walkEnd < n && sortedHits[walk.walkEnd].t <= span.tEnd)
        ++walk.walkEnd;
    DynamicRegisters r = registersAt(sortedHits, walk.walkBegin, rule, reference);
    walk.windingAtStart = r.currentIndex;
    for (std::size_t i = walk.walkBegin; i < walk.walkEnd; ++i) {
        bool crossedCurrent = false;
        const bool changed = step(r, sortedHits[i], rule, reference, crossedCurrent);
        if (crossedCurrent && (!settings.trimEnabled || changed)) {
            walk.shownIndex = std::ptrdiff_t(i);
            break;
        }
    }
    result.unresolved = r.unresolved;
    if (result.unresolved)
        walk.shownIndex = -1;
    return result;
}

PartitionCharacterization characterizeDynamicRay(std::span<const RayHit> sortedHits, DynamicRule rule,
                                                 const ReferenceClassification& reference)
{
    PartitionCharacterization out;
    DynamicRegisters r = registersAt(sortedHits, 0, rule, reference);
    out.set(r.currentBehind, r.currentInterior);
    for (const RayHit& hit : sortedHits) {
        bool crossedCurrent = false;
        step(r, hit, rule, reference, crossedCurrent);
        if (crossedCurrent)
            out.set(r.currentBehind, r.currentInterior);
    }
    out.overflowed = out.overflowed || r.unresolved;
    return out;
}

} // namespace trimlab
