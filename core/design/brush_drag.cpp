#include "core/design/brush_drag.h"

#include "core/deform/closest_surface_point.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <cstring>

namespace trimlab {

namespace {

glm::dvec3 toObject(const glm::dmat4& model, const glm::dvec3& world)
{
    return glm::dvec3(glm::inverse(model) * glm::dvec4(world, 1.0));
}

glm::dvec3 vectorToObject(const glm::dmat4& model, const glm::dvec3& world)
{
    return glm::inverse(glm::dmat3(model)) * world;
}

bool sameBits(const glm::vec3& a, const glm::vec3& b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

glm::dvec3 triangleNormal(const std::vector<glm::vec3>& positions, const glm::uvec3& t)
{
    const glm::dvec3 a(positions[t.x]), b(positions[t.y]), c(positions[t.z]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double length = glm::length(n);
    return length > 0.0 ? n / length : glm::dvec3(0.0);
}

} // namespace

// The camera basis of pixelRay: a point at view depth d lies d along the view direction,
// offset in the view plane by the pixel's position in the frustum's cross-section there.
glm::dvec3 viewPlanePoint(const DragView& view, glm::dvec2 pixel, double depth)
{
    const Camera& camera = view.camera;
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    const double width = std::max(1, view.pixelSize.x);
    const double height = std::max(1, view.pixelSize.y);
    const double halfHeight = std::tan(glm::radians(camera.fovyDegrees) * 0.5) * depth;
    const double halfWidth = halfHeight * width / height;
    const double sx = 2.0 * pixel.x / width - 1.0;
    const double sy = 1.0 - 2.0 * pixel.y / height;
    return camera.eye + forward * depth + right * (sx * halfWidth) + up * (sy * halfHeight);
}

std::optional<std::uint32_t> pickedTriangle(const TrimPixel& pixel, const DynamicFrameScene* dynamicScene)
{
    if (!pixel.covered())
        return std::nullopt;
    if (!dynamicScene)
        return std::uint32_t(pixel.primitiveId);
    if (pixel.objectId < 0 || pixel.objectId >= int(dynamicScene->meshTriangle.size()))
        return std::nullopt;
    const std::vector<std::uint32_t>& map = dynamicScene->meshTriangle[std::size_t(pixel.objectId)];
    if (std::size_t(pixel.primitiveId) >= map.size())
        return std::nullopt;
    return map[std::size_t(pixel.primitiveId)];
}

BrushPick pickAnchor(const DragView& view, glm::dvec2 pixel, std::uint32_t triangle, double viewDepth,
                     const std::vector<glm::vec3>& positions, const std::vector<glm::uvec3>& triangles,
                     const glm::dmat4& model)
{
    const glm::uvec3& t = triangles.at(triangle);
    const glm::dvec3 picked = toObject(model, viewPlanePoint(view, pixel, viewDepth));
    const glm::dvec3 anchor = deform::closestPointOnTriangle(picked, glm::dvec3(positions[t.x]),
                                                             glm::dvec3(positions[t.y]), glm::dvec3(positions[t.z]));
    return {triangle, anchor, viewDepth, pixel};
}

glm::dvec3 dragVector(const DragView& view, const BrushPick& pick, glm::dvec2 pixel, bool alongNormal,
                      const glm::dvec3& normal, const glm::dmat4& model)
{
    const glm::dvec3 world =
        viewPlanePoint(view, pixel, pick.viewDepth) - viewPlanePoint(view, pick.pixel, pick.viewDepth);
    if (!alongNormal)
        return vectorToObject(model, world);
    // The screen's up direction measures how far: up pulls out along the normal.
    const Camera& camera = view.camera;
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    const glm::dvec3 up = glm::cross(glm::normalize(glm::cross(forward, camera.up)), forward);
    const double amount = glm::dot(world, up);
    const glm::dvec3 worldNormal = glm::normalize(glm::transpose(glm::inverse(glm::dmat3(model))) * normal);
    return vectorToObject(model, worldNormal * amount);
}

BrushDrag::BrushDrag(const deform::BrushTopology& topology, const std::vector<glm::vec3>& positions,
                     const DragView& view, const BrushPick& pick, const deform::BrushSettings& settings,
                     const glm::dmat4& model)
    : m_stroke(topology, positions, deform::Stroke{pick.anchor, pick.triangle, glm::dvec3(0.0), settings}),
      m_view(view),
      m_pick(pick),
      m_model(model),
      m_normal(triangleNormal(positions, topology.triangles().at(pick.triangle))),
      m_positions(positions)
{
    m_regionStart.reserve(m_stroke.region().vertices.size());
    for (const std::uint32_t v : m_stroke.region().vertices)
        m_regionStart.push_back(positions[v]);
}

const std::vector<glm::vec3>& BrushDrag::moveTo(glm::dvec2 pixel, bool alongNormal)
{
    m_drag = dragVector(m_view, m_pick, pixel, alongNormal, m_normal, m_model);
    m_stroke.update(m_drag, m_positions);
    return m_positions;
}

timeline::Frame BrushDrag::frame() const
{
    timeline::Frame frame;
    frame.stroke = m_stroke.committed(m_drag);
    const std::vector<std::uint32_t>& region = m_stroke.region().vertices;
    for (std::size_t i = 0; i < region.size(); ++i) {
        const glm::vec3& now = m_positions[region[i]];
        if (sameBits(now, m_regionStart[i]))
            continue; // "moved" means changed bits: what undo has to restore
        frame.vertices.push_back(region[i]);
        frame.before.push_back(m_regionStart[i]);
        frame.after.push_back(now);
    }
    return frame;
}

} // namespace trimlab
