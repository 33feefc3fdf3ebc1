#pragma once
/// \file
/// Temporal coherence of a trimmed animation, measured. The thesis wants trims "coherent
/// over time" (chapter 8, introduction; 8.1.1: graphics designers "expect continuity during
/// deformation sequences") and argues that the dynamic rules, which carry the
/// classification from a reference frame (8.1.1 "Dynamic Rules", 8.1.2 Algorithms
/// 8.11–8.13), give it where the static rules do not. This file counts where a trim is not
/// coherent.
///
/// Definition. Frames t−1 and t are rendered from one camera; each pixel ray's fragments
/// of the shown frame carry the class of the space on their two sides
/// (classified_fragment.h). We track fragments, not pixels: a pixel's classification
/// depends on everything along its ray, and "nothing on the ray moved" would make a flip
/// impossible by construction under a static rule (a function of the fragments on the
/// ray) — a useless measure.
/// - A fragment of frame t−1 is **unmoved** when the same mesh triangle is hit on the same
///   pixel ray in frame t within `depthTolerance` of its depth: the surface under the
///   pixel did not move there.
/// - An unmoved fragment **flips** when the inside/outside class of the point just in
///   front of it or just behind it differs between the frames.
/// - A flip is **visible** (a trim flip) when the fragment's kept/trimmed status differs:
///   it lies on the boundary of the trimmed solid in one frame and not in the other (it
///   appears or vanishes when the solid is cut open there).
/// - A flip is **unswept** when the winding index on both sides of the fragment is the
///   same in both frames. For a closed surface the index at a point changes only when
///   some surface crosses the point, so an unswept flip is a change of class that no
///   motion at that place explains: it comes from elsewhere on the ray. A pointwise rule
///   (every static rule; a dynamic rule evaluated pointwise) cannot make one on a closed
///   surface; the thesis's walk, which decides one class per interval between current
///   fragments (Algorithm 8.13, line 13), can, and so can an open surface.
/// A pixel flips (visibly, unswept) when one of its unmoved fragments does. The measure
/// of a pair is flipping pixels / pixels with at least one unmoved fragment. Pixels
/// unresolved in either frame (a characterization over 256 layers) are left out and
/// counted.

#include "core/trim/classified_fragment.h"
#include "core/trim/frame_sequence_classifier.h"

#include <cstddef>
#include <span>

namespace trimlab {

struct PixelCoherence {
    bool unmoved = false;        ///< some fragment of the earlier frame is unmoved
    bool flipped = false;        ///< a class beside an unmoved fragment changed
    bool trimFlipped = false;    ///< an unmoved fragment's kept/trimmed status changed
    bool unsweptFlipped = false; ///< a flip where the windings on both sides did not change
};

/// One pixel: `before` and `after` are its fragments in frames t−1 and t.
[[nodiscard]] PixelCoherence comparePixel(std::span<const ClassifiedFragment> before,
                                          std::span<const ClassifiedFragment> after, double depthTolerance);

/// Pixel counts over one pair of frames.
struct CoherenceCounts {
    std::size_t comparedPixels = 0;   ///< resolved in both frames
    std::size_t unresolvedPixels = 0; ///< unresolved in either frame (left out)
    std::size_t unmovedPixels = 0;
    std::size_t flippedPixels = 0;
    std::size_t trimFlippedPixels = 0;
    std::size_t unsweptFlippedPixels = 0;

    /// count / unmovedPixels (0 without unmoved pixels).
    [[nodiscard]] double fractionOfUnmoved(std::size_t count) const
    {
        return unmovedPixels == 0 ? 0.0 : double(count) / double(unmovedPixels);
    }
};

/// Every pixel of two frames of one size (std::invalid_argument otherwise).
[[nodiscard]] CoherenceCounts compareFrames(const FrameFragments& before, const FrameFragments& after,
                                            double depthTolerance);

} // namespace trimlab
