#include "core/mesh/polygon_triangulation.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <cmath>

namespace trimlab {

namespace {

glm::dvec3 position(std::span<const glm::vec3> positions, std::uint32_t index)
{
    return glm::dvec3(positions[index]);
}

// Newell's normal: twice the vector area of the polygon, robust for non-planar and
// non-convex polygons. Computed relative to the first corner for precision.
glm::dvec3 newellNormal(std::span<const glm::vec3> positions, std::span<const std::uint32_t> polygon)
{
    const glm::dvec3 origin = position(positions, polygon[0]);
    glm::dvec3 normal(0.0);
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec3 a = position(positions, polygon[i]) - origin;
        const glm::dvec3 b = position(positions, polygon[(i + 1) % polygon.size()]) - origin;
        normal += glm::cross(a, b);
    }
    return normal;
}

void appendFan(std::span<const std::uint32_t> polygon, std::vector<glm::uvec3>& out)
{
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
        out.emplace_back(polygon[0], polygon[i], polygon[i + 1]);
}

bool facesAlong(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& normal)
{
    return glm::dot(glm::cross(b - a, c - a), normal) > 0.0;
}

void appendQuad(std::span<const glm::vec3> positions, std::span<const std::uint32_t> q, const glm::dvec3& normal,
                std::vector<glm::uvec3>& out)
{
    glm::dvec3 p[4];
    for (int i = 0; i < 4; ++i)
        p[i] = position(positions, q[i]);
    const bool diagonal02 = facesAlong(p[0], p[1], p[2], normal) && facesAlong(p[0], p[2], p[3], normal);
    const bool diagonal13 = facesAlong(p[1], p[2], p[3], normal) && facesAlong(p[1], p[3], p[0], normal);
    if (diagonal02 || !diagonal13) {
        out.emplace_back(q[0], q[1], q[2]);
        out.emplace_back(q[0], q[2], q[3]);
    } else {
        out.emplace_back(q[1], q[2], q[3]);
        out.emplace_back(q[1], q[3], q[0]);
    }
}

// Corners projected onto the plane through the first corner spanned by (u, v) with
// u × v = normal, so a polygon counter-clockwise about the normal stays counter-clockwise.
std::vector<glm::dvec2> projectToPlane(std::span<const glm::vec3> positions, std::span<const std::uint32_t> polygon,
                                       const glm::dvec3& normal)
{
    const glm::dvec3 n = glm::normalize(normal);
    const glm::dvec3 a = std::fabs(n.x) < 0.6   ? glm::dvec3(1, 0, 0)
                         : std::fabs(n.y) < 0.6 ? glm::dvec3(0, 1, 0)
                                                : glm::dvec3(0, 0, 1);
    const glm::dvec3 u = glm::normalize(glm::cross(a, n));
    const glm::dvec3 v = glm::cross(n, u);
    const glm::dvec3 origin = position(positions, polygon[0]);
    std::vector<glm::dvec2> points;
    points.reserve(polygon.size());
    for (const std::uint32_t index : polygon) {
        const glm::dvec3 d = position(positions, index) - origin;
        points.emplace_back(glm::dot(d, u), glm::dot(d, v));
    }
    return points;
}

double cross2(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c)
{
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool insideOrOn(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c)
{
    return cross2(a, b, p) >= 0.0 && cross2(b, c, p) >= 0.0 && cross2(c, a, p) >= 0.0;
}

// The polygon still to be clipped, as a cyclic doubly linked list over corner numbers.
struct EarList {
    std::vector<std::size_t> prev;
    std::vector<std::size_t> next;
    std::size_t size;

    explicit EarList(std::size_t n) : prev(n), next(n), size(n)
    {
        for (std::size_t i = 0; i < n; ++i) {
            prev[i] = (i + n - 1) % n;
            next[i] = (i + 1) % n;
        }
    }
    void remove(std::size_t i)
    {
        next[prev[i]] = next[i];
        prev[next[i]] = prev[i];
        --size;
    }
};

bool isEar(const std::vector<glm::dvec2>& points, const EarList& list, std::size_t i)
{
    const std::size_t a = list.prev[i];
    const std::size_t c = list.next[i];
    if (cross2(points[a], points[i], points[c]) <= 0.0)
        return false; // reflex or collinear corner
    for (std::size_t j = list.next[c]; j != a; j = list.next[j]) {
        if (insideOrOn(points[j], points[a], points[i], points[c]))
            return false;
    }
    return true;
}

void appendEarClipped(std::span<const glm::vec3> positions, std::span<const std::uint32_t> polygon,
                      const glm::dvec3& normal, std::vector<glm::uvec3>& out)
{
    const std::vector<glm::dvec2> points = projectToPlane(positions, polygon, normal);
    EarList list(polygon.size());
    std::size_t i = 0;
    std::size_t sinceLastEar = 0;
    while (list.size > 3) {
        if (isEar(points, list, i)) {
            out.emplace_back(polygon[list.prev[i]], polygon[i], polygon[list.next[i]]);
            const std::size_t after = list.next[i];
            list.remove(i);
            i = after;
            sinceLastEar = 0;
        } else if (++sinceLastEar > list.size) {
            break; // no ear in a full turn: self-intersecting or degenerate remainder
        } else {
            i = list.next[i];
        }
    }
    // The last triangle, or a fan over whatever could not be clipped.
    std::vector<std::uint32_t> rest;
    rest.reserve(list.size);
    std::size_t j = i;
    for (std::size_t k = 0; k < list.size; ++k, j = list.next[j])
        rest.push_back(polygon[j]);
    appendFan(rest, out);
}

} // namespace

void triangulatePolygon(std::span<const glm::vec3> positions, std::span<const std::uint32_t> polygon,
                        std::vector<glm::uvec3>& out)
{
    if (polygon.size() < 3)
        return;
    if (polygon.size() == 3) {
        out.emplace_back(polygon[0], polygon[1], polygon[2]);
        return;
    }
    const glm::dvec3 normal = newellNormal(positions, polygon);
    const double length = glm::length(normal);
    if (!(length > 0.0) || !std::isfinite(length) || polygon.size() > kMaxEarClippingCorners) {
        appendFan(polygon, out);
        return;
    }
    if (polygon.size() == 4)
        appendQuad(positions, polygon, normal, out);
    else
        appendEarClipped(positions, polygon, normal, out);
}

std::vector<glm::uvec3> triangulatePolygons(std::span<const glm::vec3> positions, const PolygonSoup& soup)
{
    std::vector<glm::uvec3> triangles;
    triangles.reserve(soup.triangleCount());
    for (std::size_t p = 0; p < soup.polygonCount(); ++p)
        triangulatePolygon(positions, soup.polygon(p), triangles);
    return triangles;
}

} // namespace trimlab
