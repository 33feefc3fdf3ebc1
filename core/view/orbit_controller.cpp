#include "core/view/orbit_controller.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace trimlab {

namespace {

constexpr glm::dvec3 kWorldUp{0.0, 1.0, 0.0};

/// Unit vector from the target to the eye for the given spherical angles.
glm::dvec3 eyeOffsetDirection(double yaw, double pitch)
{
    return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
}

/// The camera's right and up axes (the frame pixelRay uses).
struct ViewAxes {
    glm::dvec3 forward;
    glm::dvec3 right;
    glm::dvec3 up;
};

ViewAxes viewAxes(const glm::dvec3& forward)
{
    const glm::dvec3 right = glm::normalize(glm::cross(forward, kWorldUp));
    return {forward, right, glm::cross(right, forward)};
}

bool usableDirection(const glm::dvec3& v)
{
    const double length = glm::length(v);
    return std::isfinite(length) && length > 0.0;
}

} // namespace

OrbitController::OrbitController() = default;

void OrbitController::setSceneBounds(const Bounds& bounds)
{
    m_bounds = bounds;
}

double OrbitController::sceneRadius() const
{
    return m_bounds.valid() ? std::max(m_bounds.radius(), 1e-6) : 1.0;
}

double OrbitController::minDistance() const
{
    return kMinDistanceFraction * sceneRadius();
}

double OrbitController::maxDistance() const
{
    return kMaxDistanceFactor * sceneRadius();
}

glm::dvec3 OrbitController::viewDirection() const
{
    return -eyeOffsetDirection(m_yaw, m_pitch);
}

void OrbitController::fit(double aspect)
{
    setCamera(fitCamera(m_bounds, aspect > 0.0 ? aspect : 1.0));
}

void OrbitController::fit(double aspect, const glm::dvec3& viewDirection)
{
    if (!usableDirection(viewDirection)) {
        fit(aspect);
        return;
    }
    setCamera(fitCamera(m_bounds, aspect > 0.0 ? aspect : 1.0, viewDirection));
}

void OrbitController::frame(const Bounds& shown, double aspect)
{
    setCamera(fitCamera(shown.valid() ? shown : m_bounds, aspect > 0.0 ? aspect : 1.0));
}

void OrbitController::frame(const Bounds& shown, double aspect, const glm::dvec3& viewDirection)
{
    if (!usableDirection(viewDirection)) {
        frame(shown, aspect);
        return;
    }
    setCamera(fitCamera(shown.valid() ? shown : m_bounds, aspect > 0.0 ? aspect : 1.0, viewDirection));
}

void OrbitController::fitKeepingDirection(double aspect)
{
    fit(aspect, viewDirection());
}

void OrbitController::setCamera(const Camera& camera)
{
    const glm::dvec3 offset = camera.eye - camera.target;
    double length = glm::length(offset);
    glm::dvec3 direction{0.0, 0.0, 1.0};
    if (std::isfinite(length) && length > 0.0)
        direction = offset / length;
    else
        length = minDistance();
    m_target = camera.target;
    m_distance = std::clamp(length, minDistance(), maxDistance());
    m_fovyDegrees = camera.fovyDegrees;
    m_yaw = std::atan2(direction.x, direction.z);
    setPitch(std::asin(std::clamp(direction.y, -1.0, 1.0)));
}

void OrbitController::setPitch(double pitchRadians)
{
    const double limit = glm::radians(kMaxPitchDegrees);
    m_pitch = std::clamp(pitchRadians, -limit, limit);
}

void OrbitController::orbit(double yawRadians, double pitchRadians)
{
    if (!std::isfinite(yawRadians) || !std::isfinite(pitchRadians))
        return;
    m_yaw = std::remainder(m_yaw + yawRadians, 2.0 * std::numbers::pi);
    setPitch(m_pitch + pitchRadians);
}

void OrbitController::orbitByDrag(double dxPixels, double dyPixels, int viewportHeight)
{
    if (viewportHeight <= 0)
        return;
    const double radiansPerPixel = std::numbers::pi / double(viewportHeight);
    // Dragging right turns the scene right, i.e. the eye left; dragging down shows the top.
    orbit(-dxPixels * radiansPerPixel, dyPixels * radiansPerPixel);
}

void OrbitController::pan(double dxPixels, double dyPixels, int viewportHeight, double grabDepth)
{
    if (viewportHeight <= 0 || !(grabDepth > 0.0) || !std::isfinite(grabDepth))
        return;
    // World length of one pixel at view depth grabDepth (pixelRay's square pixels).
    const double tanHalf = std::tan(glm::radians(m_fovyDegrees) * 0.5);
    const double worldPerPixel = 2.0 * grabDepth * tanHalf / double(viewportHeight);
    const ViewAxes axes = viewAxes(viewDirection());
    // The camera moves against the cursor so the grabbed point moves with it.
    m_target += (-dxPixels * axes.right + dyPixels * axes.up) * worldPerPixel;
}

double OrbitController::clampedDistanceFactor(double factor) const
{
    const double wanted = std::clamp(m_distance * factor, minDistance(), maxDistance());
    return wanted / m_distance;
}

void OrbitController::zoom(double factor)
{
    if (!(factor > 0.0) || !std::isfinite(factor))
        return;
    m_distance *= clampedDistanceFactor(factor);
}

void OrbitController::zoomAt(double factor, double cursorX, double cursorY, int width, int height)
{
    if (!(factor > 0.0) || !std::isfinite(factor) || width <= 0 || height <= 0)
        return;
    const double aspect = double(width) / double(height);
    const double tanHalf = std::tan(glm::radians(m_fovyDegrees) * 0.5);
    const double ndcX = cursorX / double(width) * 2.0 - 1.0;
    const double ndcY = 1.0 - cursorY / double(height) * 2.0;
    const ViewAxes axes = viewAxes(viewDirection());
    const glm::dvec3 eye = m_target - axes.forward * m_distance;
    // Direction scaled to view depth 1, as in pixelRay: t = distance meets the target plane.
    const glm::dvec3 ray = axes.forward + axes.right * (ndcX * tanHalf * aspect) + axes.up * (ndcY * tanHalf);
    const glm::dvec3 fixedPoint = eye + ray * m_distance;
    // Scaling the whole camera about fixedPoint keeps the ray through it unchanged.
    const double f = clampedDistanceFactor(factor);
    m_target = fixedPoint + (m_target - fixedPoint) * f;
    m_distance *= f;
}

double OrbitController::wheelZoomFactor(double steps)
{
    return std::pow(0.85, steps);
}

Camera OrbitController::camera() const
{
    Camera camera;
    camera.target = m_target;
    camera.eye = m_target + eyeOffsetDirection(m_yaw, m_pitch) * m_distance;
    camera.up = kWorldUp;
    camera.fovyDegrees = m_fovyDegrees;
    return withDepthRange(camera, m_bounds);
}

} // namespace trimlab
