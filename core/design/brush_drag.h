#pragma once
/// \file
/// One brush drag in the viewport, as math: what the pixel under the cursor grabs (pick
/// → anchor on a mesh triangle, object space), how a cursor movement becomes the drag
/// vector (object space), and the timeline frame the finished drag records. The surface
/// work itself is deform::BrushStroke's.
///
/// Pixels are device pixels of the frame the pick was read from (x right, y down, (0, 0)
/// the top-left corner of the top-left pixel: the grid of pixelRay, centres at
/// half-integers). Depths are view depths: the ray parameter of pixelRay.

#include "core/deform/brush_stroke.h"
#include "core/timeline/timeline.h"
#include "core/trim/dynamic_frame_scene.h"
#include "core/trim/trim_image.h"
#include "core/view/camera.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace trimlab {

/// The view a drag happens in: the camera and size of the frame it was picked from.
struct DragView {
    Camera camera;
    glm::ivec2 pixelSize{0}; ///< x: width, y: height
};

/// The world-space point at view depth `depth` under device pixel position `pixel`.
[[nodiscard]] glm::dvec3 viewPlanePoint(const DragView& view, glm::dvec2 pixel, double depth);

/// The mesh triangle a trim pixel shows: its primitive for a static frame; under the
/// dynamic rules (`dynamicScene` given) meshTriangle[object][primitive]. nullopt for an
/// empty pixel or ids out of range.
[[nodiscard]] std::optional<std::uint32_t> pickedTriangle(const TrimPixel& pixel,
                                                          const DynamicFrameScene* dynamicScene);

/// Where a press grabs the surface.
struct BrushPick {
    std::uint32_t triangle = 0; ///< mesh triangle
    glm::dvec3 anchor{0.0};     ///< object space, on the triangle
    double viewDepth = 0.0;     ///< of the picked point
    glm::dvec2 pixel;           ///< device pixel position of the press
};

/// The anchor of a press at `pixel` on a pixel that shows `triangle` at `viewDepth`: the
/// point at that depth, mapped to object space (inverse of `model`) and snapped onto the
/// triangle at `positions` (its closest point, which absorbs the depth's rounding).
[[nodiscard]] BrushPick pickAnchor(const DragView& view, glm::dvec2 pixel, std::uint32_t triangle, double viewDepth,
                                   const std::vector<glm::vec3>& positions, const std::vector<glm::uvec3>& triangles,
                                   const glm::dmat4& model);

/// The drag of the anchor (object space) when the cursor moved from the pick to `pixel`:
/// in the view plane at the anchor's depth, so the anchor follows the cursor exactly; or,
/// `alongNormal`, along `normal` (object space, the anchor triangle's), by as much as the
/// cursor moved up the screen (down pushes inwards).
[[nodiscard]] glm::dvec3 dragVector(const DragView& view, const BrushPick& pick, glm::dvec2 pixel, bool alongNormal,
                                    const glm::dvec3& normal, const glm::dmat4& model);

/// A drag in progress: the BrushStroke built at the press and the positions it produces.
class BrushDrag {
public:
    /// Starts at `pick` on `positions` (the last frame's, #V). Throws what BrushStroke
    /// throws (invalid settings).
    BrushDrag(const deform::BrushTopology& topology, const std::vector<glm::vec3>& positions, const DragView& view,
              const BrushPick& pick, const deform::BrushSettings& settings, const glm::dmat4& model);

    /// Moves the anchor for the cursor at `pixel` and returns the deformed positions.
    const std::vector<glm::vec3>& moveTo(glm::dvec2 pixel, bool alongNormal);

    [[nodiscard]] const deform::BrushStroke& stroke() const { return m_stroke; }
    [[nodiscard]] const std::vector<glm::vec3>& positions() const { return m_positions; }
    [[nodiscard]] const BrushPick& pick() const { return m_pick; }
    /// False until the cursor left the press position (a click records no stroke).
    [[nodiscard]] bool moved() const { return m_drag != glm::dvec3(0.0); }

    /// The frame to record: the resolved stroke and exactly the region vertices whose bits
    /// changed, with their positions at the press and now.
    [[nodiscard]] timeline::Frame frame() const;

private:
    deform::BrushStroke m_stroke;
    DragView m_view;
    BrushPick m_pick;
    glm::dmat4 m_model;
    glm::dvec3 m_normal{0.0};             ///< the anchor triangle's unit normal, object space
    std::vector<glm::vec3> m_positions;   ///< #V, the deformed positions
    std::vector<glm::vec3> m_regionStart; ///< per region vertex, its position at the press
    glm::dvec3 m_drag{0.0};
};

} // namespace trimlab
