#include "skeleton_shapes.h"

#include "core/scene/shape_generators.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>

namespace trimlab::test {

TriangleMesh axisCapsule(double radius, double halfLength, int capRings, int bodyRings, int segments)
{
    std::vector<glm::dvec2> profile; // (r, y) from the south pole up to the north pole
    for (int i = 0; i <= capRings; ++i) {
        const double a = -M_PI / 2 + (M_PI / 2) * i / capRings;
        profile.emplace_back(radius * std::cos(a), -halfLength + radius * std::sin(a));
    }
    for (int i = 1; i < bodyRings; ++i)
        profile.emplace_back(radius, -halfLength + 2.0 * halfLength * i / bodyRings);
    for (int i = 0; i <= capRings; ++i) {
        const double a = (M_PI / 2) * i / capRings;
        profile.emplace_back(radius * std::cos(a), halfLength + radius * std::sin(a));
    }
    profile.front().x = 0.0; // cos(±π/2) is not exactly 0
    profile.back().x = 0.0;
    return makeSurfaceOfRevolution(profile, segments);
}

namespace {

// Cube corner c (bits x, y, z) and the 6 tetrahedra of the Kuhn split: each walks from
// corner 0 to corner 7 adding one axis at a time, in one of the 6 axis orders.
constexpr std::array<std::array<int, 4>, 6> kTetrahedra = {{
    {0, 1, 3, 7},
    {0, 1, 5, 7},
    {0, 2, 3, 7},
    {0, 2, 6, 7},
    {0, 4, 5, 7},
    {0, 4, 6, 7},
}};

class TetMesher {
public:
    TetMesher(const std::function<double(const glm::dvec3&)>& f, const glm::dvec3& lower, const glm::dvec3& upper,
              double cell)
        : m_lower(lower), m_cell(cell)
    {
        for (int a = 0; a < 3; ++a)
            m_count[a] = static_cast<int>(std::ceil((upper[a] - lower[a]) / cell)) + 1;
        m_values.resize(static_cast<std::size_t>(m_count[0]) * m_count[1] * m_count[2]);
        for (int k = 0; k < m_count[2]; ++k)
            for (int j = 0; j < m_count[1]; ++j)
                for (int i = 0; i < m_count[0]; ++i) {
                    double v = f(node(i, j, k));
                    // No grid node on or within float rounding of the surface: interpolated
                    // vertices stay ≥ 1e-3 of an edge away from the nodes, so vertices on
                    // different edges never round to one float position.
                    if (std::abs(v) < 1e-3 * cell)
                        v = 1e-3 * cell;
                    m_values[index(i, j, k)] = v;
                }
    }

    TriangleMesh run()
    {
        for (int k = 0; k + 1 < m_count[2]; ++k)
            for (int j = 0; j + 1 < m_count[1]; ++j)
                for (int i = 0; i + 1 < m_count[0]; ++i)
                    for (const std::array<int, 4>& tet : kTetrahedra) {
                        std::array<std::int64_t, 4> ids{};
                        for (int c = 0; c < 4; ++c)
                            ids[c] = static_cast<std::int64_t>(
                                index(i + (tet[c] & 1), j + ((tet[c] >> 1) & 1), k + ((tet[c] >> 2) & 1)));
                        tetrahedron(ids);
                    }
        return std::move(m_mesh);
    }

private:
    [[nodiscard]] std::size_t index(int i, int j, int k) const
    {
        return (static_cast<std::size_t>(k) * m_count[1] + j) * m_count[0] + i;
    }
    [[nodiscard]] glm::dvec3 node(int i, int j, int k) const { return m_lower + m_cell * glm::dvec3(i, j, k); }
    [[nodiscard]] glm::dvec3 node(std::int64_t id) const
    {
        const auto n = static_cast<std::int64_t>(m_count[0]) * m_count[1];
        return node(static_cast<int>(id % m_count[0]), static_cast<int>((id % n) / m_count[0]),
                    static_cast<int>(id / n));
    }

    // The surface vertex on grid edge (inside a, outside b), shared by all its tetrahedra.
    unsigned edgeVertex(std::int64_t a, std::int64_t b)
    {
        const std::int64_t key = std::min(a, b) * static_cast<std::int64_t>(m_values.size()) + std::max(a, b);
        if (const auto it = m_edgeVertices.find(key); it != m_edgeVertices.end())
            return it->second;
        const double fa = m_values[static_cast<std::size_t>(a)], fb = m_values[static_cast<std::size_t>(b)];
        const double t = fa / (fa - fb);
        const glm::dvec3 p = node(a) + t * (node(b) - node(a));
        const auto id = static_cast<unsigned>(m_mesh.positions.size());
        m_mesh.positions.emplace_back(p);
        m_edgeVertices.emplace(key, id);
        return id;
    }

    // Adds the polygon across the grid edges `crossing` (inside node, outside node),
    // listed in cyclic order, as a fan of triangles facing outside. The facing is decided
    // on the polygon of the edge midpoints — the section that separates the tetrahedron's
    // inside corners from its outside ones, never degenerate — so it does not depend on
    // where the interpolated vertices fall (near a node they may nearly coincide).
    void polygon(std::vector<std::pair<std::int64_t, std::int64_t>> crossing)
    {
        const auto mid = [&](const std::pair<std::int64_t, std::int64_t>& e) {
            return 0.5 * (node(e.first) + node(e.second));
        };
        const glm::dvec3 normal = glm::cross(mid(crossing[1]) - mid(crossing[0]), mid(crossing[2]) - mid(crossing[0]));
        if (glm::dot(normal, node(crossing[0].second) - node(crossing[0].first)) < 0.0)
            std::reverse(crossing.begin(), crossing.end());
        std::vector<unsigned> v;
        for (const auto& e : crossing)
            v.push_back(edgeVertex(e.first, e.second));
        for (std::size_t k = 1; k + 1 < v.size(); ++k)
            m_mesh.triangles.emplace_back(v[0], v[k], v[k + 1]);
    }

    void tetrahedron(const std::array<std::int64_t, 4>& ids)
    {
        std::array<std::int64_t, 4> in{}, out{};
        int inCount = 0, outCount = 0;
        for (std::int64_t id : ids)
            (m_values[static_cast<std::size_t>(id)] < 0.0 ? in[inCount++] : out[outCount++]) = id;
        if (inCount == 1) // one corner inside: a triangle across its three edges
            polygon({{in[0], out[0]}, {in[0], out[1]}, {in[0], out[2]}});
        else if (inCount == 3) // one corner outside
            polygon({{in[0], out[0]}, {in[1], out[0]}, {in[2], out[0]}});
        else if (inCount == 2) // a quad across the four edges between the two sides
            polygon({{in[0], out[0]}, {in[0], out[1]}, {in[1], out[1]}, {in[1], out[0]}});
    }

    glm::dvec3 m_lower;
    double m_cell;
    std::array<int, 3> m_count{};
    std::vector<double> m_values;
    std::unordered_map<std::int64_t, unsigned> m_edgeVertices;
    TriangleMesh m_mesh;
};

double capsuleDistance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, double radius)
{
    const glm::dvec3 ab = b - a;
    const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
    return glm::length(p - (a + t * ab)) - radius;
}

// Polynomial smooth minimum with blend radius k.
double smoothMin(double a, double b, double k)
{
    const double h = std::clamp(0.5 + 0.5 * (b - a) / k, 0.0, 1.0);
    return b + (a - b) * h - k * h * (1.0 - h);
}

} // namespace

TriangleMesh marchingTetrahedra(const std::function<double(const glm::dvec3&)>& f, const glm::dvec3& lower,
                                const glm::dvec3& upper, double cell)
{
    return TetMesher(f, lower, upper, cell).run();
}

glm::dvec3 Star::armDirection(std::size_t k) const
{
    const double angle = 2.0 * M_PI * static_cast<double>(k) / static_cast<double>(armLengths.size()) + 0.3;
    return {std::cos(angle), 0.0, std::sin(angle)};
}

double Star::implicit(const glm::dvec3& p) const
{
    double value = glm::length(p) - hubRadius;
    for (std::size_t k = 0; k < armLengths.size(); ++k)
        value = smoothMin(value, capsuleDistance(p, glm::dvec3(0.0), armLengths[k] * armDirection(k), armRadius),
                          0.5 * armRadius);
    return value;
}

TriangleMesh Star::mesh(double cell) const
{
    const double reach = *std::max_element(armLengths.begin(), armLengths.end()) + armRadius + 2.0 * cell;
    const double height = std::max(hubRadius, armRadius) + 2.0 * cell;
    return marchingTetrahedra([this](const glm::dvec3& p) { return implicit(p); }, glm::dvec3(-reach, -height, -reach),
                              glm::dvec3(reach, height, reach), cell);
}

glm::dvec3 Fork::prongTip(int side) const
{
    return glm::dvec3(stemLength, 0.0, 0.0) +
           prongLength * glm::dvec3(std::cos(spread), 0.0, double(side) * std::sin(spread));
}

double Fork::implicit(const glm::dvec3& p) const
{
    const glm::dvec3 stemEnd(stemLength, 0.0, 0.0);
    double value = capsuleDistance(p, glm::dvec3(-handleLength, 0.0, 0.0), glm::dvec3(0.0), handleRadius);
    value = smoothMin(value, capsuleDistance(p, glm::dvec3(0.0), stemEnd, prongRadius), 0.5 * prongRadius);
    for (const int side : {-1, 1})
        value = smoothMin(value, capsuleDistance(p, stemEnd, prongTip(side), prongRadius), 0.5 * prongRadius);
    return value;
}

TriangleMesh Fork::mesh(double cell) const
{
    const double margin = std::max(handleRadius, prongRadius) + 2.0 * cell;
    const double reach = std::max(prongTip(1).z, 0.0) + margin;
    return marchingTetrahedra([this](const glm::dvec3& p) { return implicit(p); },
                              glm::dvec3(-handleLength - margin, -margin, -reach),
                              glm::dvec3(prongTip(1).x + margin, margin, reach), cell);
}

} // namespace trimlab::test
