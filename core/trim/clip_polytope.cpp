#include "core/trim/clip_polytope.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace trimlab {

namespace {

// A plane keeping n·x + d >= 0, n of unit length.
struct HalfSpace {
    glm::dvec3 n;
    double d;

    [[nodiscard]] double evaluate(const glm::dvec3& p) const { return glm::dot(n, p) + d; }
};

std::vector<HalfSpace> halfSpaces(const ClipSet& clips, const Bounds& box)
{
    std::vector<HalfSpace> spaces;
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 n(0.0);
        n[axis] = 1.0;
        spaces.push_back({n, -box.min[axis]});
        spaces.push_back({-n, box.max[axis]});
    }
    for (const ClipPlane& plane : clips.planes) {
        const double length = glm::length(plane.normal);
        if (plane.enabled && length > 0.0)
            spaces.push_back({plane.normal / length, plane.offset / length});
    }
    return spaces;
}

// The point on all three planes, or nullopt when they do not meet in one point.
std::optional<glm::dvec3> meet(const HalfSpace& a, const HalfSpace& b, const HalfSpace& c)
{
    const glm::dvec3 bc = glm::cross(b.n, c.n);
    const double det = glm::dot(a.n, bc);
    if (std::abs(det) < 1e-12)
        return std::nullopt;
    return (-a.d * bc - b.d * glm::cross(c.n, a.n) - c.d * glm::cross(a.n, b.n)) / det;
}

} // namespace

TriangleMesh clipPolytope(const ClipSet& clips, const Bounds& box)
{
    TriangleMesh mesh;
    if (!box.valid())
        return mesh;
    const std::vector<HalfSpace> spaces = halfSpaces(clips, box);
    const double tolerance = 1e-9 * std::max(glm::length(box.max - box.min), 1e-30);
    std::vector<glm::dvec3> vertices;
    for (std::size_t i = 0; i < spaces.size(); ++i)
        for (std::size_t j = i + 1; j < spaces.size(); ++j)
            for (std::size_t k = j + 1; k < spaces.size(); ++k) {
                const std::optional<glm::dvec3> p = meet(spaces[i], spaces[j], spaces[k]);
                if (!p || std::any_of(spaces.begin(), spaces.end(),
                                      [&](const HalfSpace& s) { return s.evaluate(*p) < -tolerance; }))
                    continue;
                if (std::none_of(vertices.begin(), vertices.end(),
                                 [&](const glm::dvec3& v) { return glm::length(v - *p) <= 10.0 * tolerance; }))
                    vertices.push_back(*p);
            }
    if (vertices.size() < 4)
        return mesh;
    for (const glm::dvec3& v : vertices)
        mesh.positions.push_back(glm::vec3(v));
    for (const HalfSpace& space : spaces) {
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
        const glm::dvec3 outward = -space.n;
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
