#pragma once
/// \file
/// The interactive camera of the viewport as pure math: orbit about a target (yaw about
/// world +y, pitch clamped short of the poles), pan in the view plane, multiplicative
/// dolly toward the target (optionally toward the point under the cursor), and fit to the
/// scene bounds. Every Camera it hands out has withDepthRange applied, so the far plane
/// always lies beyond the whole scene (the trim renderer counts the winding index from
/// the far side; a scene point behind the far plane would corrupt that count).
///
/// Pixel arguments use the viewport's pixel grid: x to the right, y down, (0, 0) at the
/// top-left corner of the top-left pixel (the grid of pixelRay, whose pixel centres lie
/// at half-integers). Only the ratio of a drag to the viewport height matters, so
/// logical and device pixels work alike as long as one call does not mix them.

#include "core/view/camera.h"

#include <glm/vec3.hpp>

namespace trimlab {

class OrbitController {
public:
    /// Pitch never reaches ±90°, so the world +y "up" vector stays usable.
    static constexpr double kMaxPitchDegrees = 89.0;
    /// The closest the eye may come to the target, as a fraction of the scene radius
    /// (the dolly slows down multiplicatively and stops there: it never passes through).
    static constexpr double kMinDistanceFraction = 1e-3;
    /// The farthest the eye may go, as a multiple of the scene radius.
    static constexpr double kMaxDistanceFactor = 1e3;

    /// A camera at Camera's defaults (eye on +z looking at the origin), no scene bounds.
    OrbitController();

    /// The box the far plane must enclose and fit() frames. An invalid (empty) box is
    /// allowed: the depth range is then left as Camera's defaults and the scene radius
    /// taken as 1.
    void setSceneBounds(const Bounds& bounds);
    [[nodiscard]] const Bounds& sceneBounds() const { return m_bounds; }

    /// Frames the scene along fitCamera's default view direction (the "reset view").
    /// `aspect` = viewport width / height.
    void fit(double aspect);
    /// Frames the scene looking along `viewDirection` (eye → target, any length > 0).
    void fit(double aspect, const glm::dvec3& viewDirection);
    /// Frames the scene keeping the current view direction ("fit to view").
    void fitKeepingDirection(double aspect);
    /// The same three framings of `shown` (what the view shows now: the current pose and
    /// anything drawn over it, such as a control net) instead of the scene bounds, which
    /// may hold every frame of a history; the depth range still encloses the scene
    /// bounds. An invalid `shown` frames the scene bounds.
    void frame(const Bounds& shown, double aspect);
    void frame(const Bounds& shown, double aspect, const glm::dvec3& viewDirection);

    /// Adopts `camera`'s eye, target and fovy; its up vector and depth range are replaced
    /// (world +y, withDepthRange). A pitch beyond kMaxPitchDegrees is clamped, which moves
    /// the eye; an eye on the target is moved to the minimum distance along +z.
    void setCamera(const Camera& camera);

    /// Turns the eye about the target: `yawRadians` is a right-handed turn about world +y
    /// (the eye at +z moves toward +x), positive `pitchRadians` raises the eye. The pitch
    /// is clamped to ±kMaxPitchDegrees.
    void orbit(double yawRadians, double pitchRadians);
    /// A mouse drag of (dx, dy) pixels in a viewport `viewportHeight` pixels tall: the
    /// scene turns with the cursor, 180° per viewport height. Non-positive heights are
    /// ignored.
    void orbitByDrag(double dxPixels, double dyPixels, int viewportHeight);

    /// Moves eye and target together in the view plane so that a point at view depth
    /// `grabDepth` follows the cursor's (dx, dy) pixels exactly. Use the depth of the
    /// surface under the cursor when there is one, else distance(). Non-positive depths
    /// or heights are ignored.
    void pan(double dxPixels, double dyPixels, int viewportHeight, double grabDepth);

    /// Dollies toward the target: distance *= factor (< 1 moves closer), clamped to
    /// [minDistance(), maxDistance()]. Non-positive or non-finite factors are ignored.
    void zoom(double factor);
    /// Like zoom(), but scales the camera about the point of the target's view plane
    /// under the cursor (cursorX, cursorY) of a width×height viewport, so that point
    /// stays under the cursor (the target moves toward it).
    void zoomAt(double factor, double cursorX, double cursorY, int width, int height);
    /// The zoom factor of `steps` wheel notches (positive = away from the user, zooms in).
    [[nodiscard]] static double wheelZoomFactor(double steps);

    /// The camera to render with, depth range enclosing the scene bounds.
    [[nodiscard]] Camera camera() const;

    [[nodiscard]] const glm::dvec3& target() const { return m_target; }
    [[nodiscard]] double distance() const { return m_distance; }
    [[nodiscard]] double yawRadians() const { return m_yaw; }
    [[nodiscard]] double pitchRadians() const { return m_pitch; }
    /// Unit vector from the eye to the target.
    [[nodiscard]] glm::dvec3 viewDirection() const;
    [[nodiscard]] double minDistance() const;
    [[nodiscard]] double maxDistance() const;

private:
    [[nodiscard]] double sceneRadius() const;
    [[nodiscard]] double clampedDistanceFactor(double factor) const;
    void setPitch(double pitchRadians);

    Bounds m_bounds;
    glm::dvec3 m_target{0.0};
    double m_distance = 3.0;
    double m_yaw = 0.0;
    double m_pitch = 0.0;
    double m_fovyDegrees = 45.0;
};

} // namespace trimlab
