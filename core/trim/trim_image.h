#pragma once
/// \file
/// The per-pixel answer of a trim render: which surface point a pixel shows and why.
/// Both the GPU backends (read back from their id attachment) and the CPU reference fill
/// this, so tests compare them field by field.

#include <cstdint>
#include <limits>
#include <vector>

namespace trimlab {

/// Result of one pixel. An empty pixel (no trim fragment in the kept span) has
/// primitiveId == -1 and facing == 0.
struct TrimPixel {
    /// View depth of the shown point (the ray parameter t of PixelRay); +inf when empty.
    float viewDepth = std::numeric_limits<float>::infinity();
    std::int32_t primitiveId = -1; ///< triangle index within its object
    std::int32_t objectId = -1;    ///< index into Scene::objects
    std::int8_t facing = 0;        ///< +1 front-facing, −1 back-facing, 0 empty
    /// Winding index at the start of the kept span (near plane or clip plane).
    std::int32_t windingAtStart = 0;
    /// GPU methods with a capacity: the pixel lost fragments (more than it could hold).
    bool overflowed = false;
    /// The pixel lost fragments and its trim point may have been among them, so it shows
    /// nothing (painted as unresolved) rather than something wrong. Set by the CPU
    /// reference only where a dynamic rule's reference characterization overflowed.
    bool unresolved = false;
    /// Capping (CapSettings): the pixel shows the cap of this plane of the ClipSet (0 ..
    /// kMaxClipPlanes − 1) at viewDepth = the span start; primitiveId and objectId are −1
    /// and facing 0 then. −1: no cap.
    std::int8_t capPlane = -1;
    /// HighlightSettings::collisions: the shown fragment lies inside another object or
    /// where its own object overlaps itself. Always false with the highlight off.
    bool collision = false;
    /// HighlightSettings::coplanar: fragments of the kept span at exactly the shown
    /// fragment's depth, the shown one included (>= 1 when a fragment is shown; 2 or more
    /// is a coplanar group). Always 0 with the highlight off or for an empty pixel or cap.
    std::uint8_t coplanarCount = 0;

    /// The pixel shows something: a surface fragment or a cap.
    [[nodiscard]] bool covered() const { return primitiveId >= 0 || capPlane >= 0; }
    [[nodiscard]] bool isCap() const { return capPlane >= 0; }
};

/// A width×height image of TrimPixel, row 0 at the top.
struct TrimImage {
    int width = 0;
    int height = 0;
    std::vector<TrimPixel> pixels;

    TrimImage() = default;
    TrimImage(int w, int h) : width(w), height(h), pixels(std::size_t(w) * std::size_t(h)) {}
    [[nodiscard]] TrimPixel& at(int x, int y) { return pixels[std::size_t(y) * width + x]; }
    [[nodiscard]] const TrimPixel& at(int x, int y) const { return pixels[std::size_t(y) * width + x]; }
};

} // namespace trimlab
