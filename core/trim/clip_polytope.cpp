#include "core/trim/clip_polytope.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace trimlab {

namespace {

// The box's six planes and the enabled clipping planes, each with a unit normal.
std::vector<ClipPlane> halfSpaces(const ClipSet& clips, const Bounds& box)
{
    std::vector<ClipPlane> spaces;
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 n(0.0);
        n[axis] = 1.0;
        spaces.push_back({true, n, -box.min[axis]});
        spaces.push_back({true, -n, box.max[axis]});
    }
    for (const ClipPlane& plane : clips.planes) {
        const double length = glm::length(plane.normal);
        if (plane.enabled && length > 0.0)
            spaces.push_back({true, plane.normal / length, plane.offset / length});
    }
    return spaces;
}

// The point on all three planes, or nullopt when they do not meet in one point.
std::optional<glm::dvec3> meet(const ClipPlane& a, const ClipPlane& b, const ClipPlane& c)
{
    const glm::dvec3 bc = glm::cross(b.normal, c.normal);
    const double det = glm::dot(a.normal, bc);
    if (std::abs(det) < 1e-12)
        return std::nullopt;
    return (-a.offset * bc - b.offset * glm::cross(c.normal, a.normal) - c.offset * glm::cross(a.normal, b.normal)) /
           det;
}

} // namespace

TriangleMesh clipPolytope(const ClipSet& clips, const Bounds& box)
{
    TriangleMesh mesh;
    if (!box.valid())
        return mesh;
    const std::vector<ClipPlane> spaces = halfSpaces(clips, box);
    const double tolerance = 1e-9 * std::max(glm::length(box.max - box.min), 1e-30);
    std::vector<glm::dvec3> vertices;
    for (std::size_t i = 0; i < spaces.size(); ++i)
        for (std::size_t j = i + 1; j < spaces.size(); ++j)
            for (std::size_t k = j + 1; k < spaces.size(); ++k) {
                const std::optional<glm::dvec3> p = meet(spaces[i], spaces[j], spaces[k]);
                if (!p || std::any_of(spaces.begin(), spaces.end(),
                                      [&](const ClipPlane& s) { return s.evaluate(*p) < -tolerance; }))
                    continue;
                if (std::none_of(vertices.begin(), vertices.end(),
                                 [&](const glm::dvec3& v) { return glm::length(v - *p) <= 10.0 * tolerance; }))
                    vertices.push_back(*p);
            }
    if (vertices.size() < 4)
        return mesh;
    for (const glm::dvec3& v : vertices)
        mesh.positions.push_back(glm::vec3(v));
    for (const ClipPlane& space : spaces) {
        std::vector<std::uint32_t> face;
        for (std::uint32_t v = 0; v < vertices.size(); ++v)
            if (std::abs(space.evaluate(vertices[v])) <= 10.0 * tolerance)
                face.push_back(v);
        if (face.size() < 3)
            continue;
        // Counter-clockwise seen from outside, along the outward normal −n.
        glm::dvec3 faceCentre(0.0);
        for (std::uint32_t v : face)
            faceCentre += vertices[v];
        faceCentre /= double(face.size());
        const glm::dvec3 outward = -space.normal;
        const glm::dvec3 u = glm::normalize(vertices[face.front()] - faceCentre);
        const glm::dvec3 w = glm::cross(outward, u);
        const auto angle = [&](std::uint32_t v) {
            const glm::dvec3 r = vertices[v] - faceCentre;
            return std::atan2(glm::dot(r, w), glm::dot(r, u));
        };
        std::sort(face.begin(), face.end(), [&](std::uint32_t a, std::uint32_t b) { return angle(a) < angle(b); });
        for (std::size_t i = 1; i + 1 < face.size(); ++i)
            mesh.triangles.emplace_back(face[0], face[i], face[i + 1]);
    }
    return mesh;
}

} // namespace trimlab
