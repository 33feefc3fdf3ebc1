#include "core/scene/shape_generators.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace trimlab {

namespace {

void flipOrientation(TriangleMesh& mesh)
{
    for (glm::uvec3& t : mesh.triangles)
        std::swap(t[1], t[2]);
}

// Maps unit-space positions to center + radius·p (in double, one rounding to float).
void placeAt(TriangleMesh& mesh, const glm::dvec3& center, double radius)
{
    for (glm::vec3& p : mesh.positions)
        p = glm::vec3(center + radius * glm::dvec3(p));
}

glm::dvec3 rotateAbout(const glm::dvec3& v, const glm::dvec3& unitAxis, double cosAngle, double sinAngle)
{
    return v * cosAngle + glm::cross(unitAxis, v) * sinAngle + unitAxis * glm::dot(unitAxis, v) * (1.0 - cosAngle);
}

// The unit icosahedron: 12 vertices (0, ±1, ±φ) cyclically permuted; its faces are the
// triples of mutually adjacent vertices (distance 2), oriented outward.
void makeIcosahedron(std::vector<glm::dvec3>& vertices, std::vector<glm::uvec3>& faces)
{
    const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
    for (double s1 : {-1.0, 1.0}) {
        for (double s2 : {-1.0, 1.0}) {
            vertices.push_back({0.0, s1, s2 * phi});
            vertices.push_back({s1, s2 * phi, 0.0});
            vertices.push_back({s2 * phi, 0.0, s1});
        }
    }
    auto adjacent = [&](unsigned i, unsigned j) {
        return std::abs(glm::dot(vertices[i] - vertices[j], vertices[i] - vertices[j]) - 4.0) < 1e-9;
    };
    for (unsigned i = 0; i < 12; ++i)
        for (unsigned j = i + 1; j < 12; ++j)
            for (unsigned k = j + 1; k < 12; ++k) {
                if (!adjacent(i, j) || !adjacent(j, k) || !adjacent(i, k))
                    continue;
                const glm::dvec3 n = glm::cross(vertices[j] - vertices[i], vertices[k] - vertices[i]);
                const bool out = glm::dot(n, vertices[i] + vertices[j] + vertices[k]) > 0.0;
                faces.push_back(out ? glm::uvec3(i, j, k) : glm::uvec3(i, k, j));
            }
    for (glm::dvec3& v : vertices)
        v = glm::normalize(v);
}

// One 1-to-4 split of every face, midpoints projected to the unit sphere.
void subdivideOnSphere(std::vector<glm::dvec3>& vertices, std::vector<glm::uvec3>& faces)
{
    std::map<std::pair<unsigned, unsigned>, unsigned> midpoints;
    auto midpoint = [&](unsigned a, unsigned b) {
        const auto key = std::minmax(a, b);
        const auto found = midpoints.find(key);
        if (found != midpoints.end())
            return found->second;
        vertices.push_back(glm::normalize(vertices[a] + vertices[b]));
        const auto index = unsigned(vertices.size() - 1);
        midpoints.emplace(key, index);
        return index;
    };
    std::vector<glm::uvec3> finer;
    finer.reserve(faces.size() * 4);
    for (const glm::uvec3& f : faces) {
        const unsigned ab = midpoint(f[0], f[1]);
        const unsigned bc = midpoint(f[1], f[2]);
        const unsigned ca = midpoint(f[2], f[0]);
        finer.push_back({f[0], ab, ca});
        finer.push_back({ab, f[1], bc});
        finer.push_back({ca, bc, f[2]});
        finer.push_back({ab, bc, ca});
    }
    faces = std::move(finer);
}

bool validProfile(std::span<const glm::dvec2> profile)
{
    if (profile.size() < 3 || profile.front().x != 0.0 || profile.back().x != 0.0)
        return false;
    return std::all_of(profile.begin() + 1, profile.end() - 1, [](const glm::dvec2& p) { return p.x > 0.0; });
}

// Unit tangents of a closed polyline (central differences); empty if one vanishes.
std::vector<glm::dvec3> closedTangents(std::span<const glm::dvec3> curve)
{
    const std::size_t n = curve.size();
    std::vector<glm::dvec3> tangents(n);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3 d = curve[(i + 1) % n] - curve[(i + n - 1) % n];
        const double length = glm::length(d);
        if (!(length > 0.0) || curve[(i + 1) % n] == curve[i])
            return {};
        tangents[i] = d / length;
    }
    return tangents;
}

// Section normals by parallel transport (minimal rotation between consecutive tangents),
// with the closing twist spread evenly so the frame at n meets the frame at 0.
std::vector<glm::dvec3> transportedNormals(const std::vector<glm::dvec3>& tangents)
{
    const std::size_t n = tangents.size();
    const glm::dvec3& t0 = tangents[0];
    const glm::dvec3 absT = glm::abs(t0);
    const int axis = absT.x <= absT.y ? (absT.x <= absT.z ? 0 : 2) : (absT.y <= absT.z ? 1 : 2);
    glm::dvec3 seed(0.0);
    seed[axis] = 1.0;
    std::vector<glm::dvec3> normals(n + 1);
    normals[0] = glm::normalize(seed - t0 * glm::dot(seed, t0));
    for (std::size_t i = 1; i <= n; ++i) {
        const glm::dvec3& from = tangents[i - 1];
        const glm::dvec3& to = tangents[i % n];
        const glm::dvec3 axisVector = glm::cross(from, to);
        const double sinAngle = glm::length(axisVector);
        glm::dvec3 next = normals[i - 1];
        if (sinAngle > 1e-15)
            next = rotateAbout(next, axisVector / sinAngle, glm::dot(from, to), sinAngle);
        normals[i] = glm::normalize(next - to * glm::dot(next, to));
    }
    const double twist = std::atan2(glm::dot(glm::cross(normals[0], normals[n]), t0), glm::dot(normals[0], normals[n]));
    normals.pop_back();
    for (std::size_t i = 1; i < n; ++i) {
        const double angle = -twist * double(i) / double(n);
        normals[i] = rotateAbout(normals[i], tangents[i], std::cos(angle), std::sin(angle));
    }
    return normals;
}

} // namespace

TriangleMesh makeSurfaceOfRevolution(std::span<const glm::dvec2> profile, int segments)
{
    TriangleMesh mesh;
    if (segments < 3 || !validProfile(profile))
        return mesh;
    const auto m = unsigned(segments);
    const auto rings = unsigned(profile.size() - 2); // inner profile points
    mesh.positions.push_back(glm::vec3(0.0, profile.front().y, 0.0));
    for (unsigned i = 1; i <= rings; ++i) {
        for (unsigned j = 0; j < m; ++j) {
            const double angle = 2.0 * glm::pi<double>() * j / m;
            const glm::dvec2& p = profile[i];
            mesh.positions.push_back(glm::vec3(p.x * std::cos(angle), p.y, p.x * std::sin(angle)));
        }
    }
    mesh.positions.push_back(glm::vec3(0.0, profile.back().y, 0.0));
    const unsigned lastPole = 1 + rings * m;
    auto vertex = [&](unsigned i, unsigned j) { return i == 0 ? 0u : i > rings ? lastPole : 1 + (i - 1) * m + j % m; };
    for (unsigned i = 0; i <= rings; ++i) {
        for (unsigned j = 0; j < m; ++j) {
            // Quad (i, j)-(i+1, j)-(i+1, j+1)-(i, j+1); T × R points outward (see header).
            if (i < rings)
                mesh.triangles.push_back({vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)});
            if (i > 0)
                mesh.triangles.push_back({vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
        }
    }
    return mesh;
}

TriangleMesh makeUvSphere(const glm::dvec3& center, double radius, int rings, int segments, bool outward)
{
    if (!(radius > 0.0) || rings < 2)
        return {};
    std::vector<glm::dvec2> profile;
    for (int k = 0; k <= rings; ++k) {
        const double theta = glm::pi<double>() * k / rings;
        const bool pole = k == 0 || k == rings;
        profile.push_back({pole ? 0.0 : std::sin(theta), -std::cos(theta)});
    }
    TriangleMesh mesh = makeSurfaceOfRevolution(profile, segments);
    placeAt(mesh, center, radius);
    if (!outward)
        flipOrientation(mesh);
    return mesh;
}

TriangleMesh makeIcosphere(const glm::dvec3& center, double radius, int subdivisions, bool outward)
{
    TriangleMesh mesh;
    if (!(radius > 0.0) || subdivisions < 0 || subdivisions > 8)
        return mesh;
    std::vector<glm::dvec3> vertices;
    std::vector<glm::uvec3> faces;
    makeIcosahedron(vertices, faces);
    for (int s = 0; s < subdivisions; ++s)
        subdivideOnSphere(vertices, faces);
    for (const glm::dvec3& v : vertices)
        mesh.positions.push_back(glm::vec3(center + radius * v));
    mesh.triangles = std::move(faces);
    if (!outward)
        flipOrientation(mesh);
    return mesh;
}

TriangleMesh makeTube(std::span<const glm::dvec3> closedCurve, double radius, int sides, bool outward)
{
    TriangleMesh mesh;
    if (closedCurve.size() < 3 || sides < 3 || !(radius > 0.0))
        return mesh;
    const std::vector<glm::dvec3> tangents = closedTangents(closedCurve);
    if (tangents.empty())
        return mesh;
    const std::vector<glm::dvec3> normals = transportedNormals(tangents);
    const auto n = unsigned(closedCurve.size());
    const auto m = unsigned(sides);
    for (unsigned i = 0; i < n; ++i) {
        const glm::dvec3 binormal = glm::cross(tangents[i], normals[i]);
        for (unsigned k = 0; k < m; ++k) {
            const double angle = 2.0 * glm::pi<double>() * k / m;
            const glm::dvec3 offset = std::cos(angle) * normals[i] + std::sin(angle) * binormal;
            mesh.positions.push_back(glm::vec3(closedCurve[i] + radius * offset));
        }
    }
    auto vertex = [&](unsigned i, unsigned k) { return (i % n) * m + k % m; };
    for (unsigned i = 0; i < n; ++i) {
        for (unsigned k = 0; k < m; ++k) {
            // d(section angle) × tangent is the outward normal.
            mesh.triangles.push_back({vertex(i, k), vertex(i, k + 1), vertex(i + 1, k + 1)});
            mesh.triangles.push_back({vertex(i, k), vertex(i + 1, k + 1), vertex(i + 1, k)});
        }
    }
    if (!outward)
        flipOrientation(mesh);
    return mesh;
}

TriangleMesh makeTorus(const glm::dvec3& center, double majorRadius, double minorRadius, int majorSegments,
                       int minorSegments, bool outward)
{
    if (!(minorRadius > 0.0 && minorRadius < majorRadius) || majorSegments < 3)
        return {};
    std::vector<glm::dvec3> circle;
    for (int j = 0; j < majorSegments; ++j) {
        const double angle = 2.0 * glm::pi<double>() * j / majorSegments;
        circle.push_back(center + majorRadius * glm::dvec3(std::cos(angle), 0.0, std::sin(angle)));
    }
    return makeTube(circle, minorRadius, minorSegments, outward);
}

TriangleMesh makeBox(const glm::dvec3& lower, const glm::dvec3& upper, bool outward)
{
    if (!(lower.x < upper.x && lower.y < upper.y && lower.z < upper.z))
        return {};
    TriangleMesh mesh;
    // Vertex index bit k set: coordinate k at `upper`.
    for (unsigned i = 0; i < 8; ++i)
        mesh.positions.emplace_back(
            glm::dvec3((i & 1u) ? upper.x : lower.x, (i & 2u) ? upper.y : lower.y, (i & 4u) ? upper.z : lower.z));
    for (unsigned axis = 0; axis < 3; ++axis) {
        // (u, v) the other two axes in cyclic order, so u × v points along +axis.
        const unsigned u = 1u << ((axis + 1) % 3);
        const unsigned v = 1u << ((axis + 2) % 3);
        for (unsigned side = 0; side < 2; ++side) {
            const unsigned base = side ? 1u << axis : 0u;
            const unsigned c00 = base, c10 = base | u, c11 = base | u | v, c01 = base | v;
            // Counter-clockwise seen from outside: (u, v) order on the + side, reversed on the − side.
            const bool forward = (side == 1) == outward;
            if (forward) {
                mesh.triangles.push_back({c00, c10, c11});
                mesh.triangles.push_back({c00, c11, c01});
            } else {
                mesh.triangles.push_back({c00, c11, c10});
                mesh.triangles.push_back({c00, c01, c11});
            }
        }
    }
    return mesh;
}

} // namespace trimlab
