#include "core/surface/subdivision_cages.h"

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <stdexcept>
#include <tuple>

namespace trimlab {

namespace {

void addFace(SubdivisionCage& cage, std::initializer_list<std::uint32_t> corners)
{
    cage.faceSizes.push_back(std::uint32_t(corners.size()));
    cage.faceIndices.insert(cage.faceIndices.end(), corners);
}

using Cell = std::array<int, 3>;

// The boundary of a union of unit cubes (cells of the integer grid) as outward quads.
SubdivisionCage voxelCage(const std::set<Cell>& cells)
{
    SubdivisionCage cage;
    std::map<Cell, std::uint32_t> vertexIds;
    const auto vertex = [&](const Cell& p) {
        const auto [it, inserted] = vertexIds.try_emplace(p, std::uint32_t(cage.positions.size()));
        if (inserted)
            cage.positions.emplace_back(p[0], p[1], p[2]);
        return it->second;
    };
    for (const Cell& c : cells) {
        for (int axis = 0; axis < 3; ++axis) {
            for (const int side : {-1, 1}) {
                Cell n = c;
                n[std::size_t(axis)] += side;
                if (cells.contains(n))
                    continue;
                // The face lies in the plane axis = c[axis] + (side > 0); u, v span the other
                // two axes, ordered so that (u × v) points along +axis, reversed for side < 0.
                const std::size_t a = std::size_t(axis), u = (a + 1) % 3, v = (a + 2) % 3;
                Cell p0 = c;
                p0[a] += side > 0 ? 1 : 0;
                Cell p1 = p0, p2 = p0, p3 = p0;
                p1[u] += 1;
                p2[u] += 1;
                p2[v] += 1;
                p3[v] += 1;
                if (side > 0)
                    addFace(cage, {vertex(p0), vertex(p1), vertex(p2), vertex(p3)});
                else
                    addFace(cage, {vertex(p0), vertex(p3), vertex(p2), vertex(p1)});
            }
        }
    }
    return cage;
}

} // namespace

SubdivisionCage cubeCage(double halfSize)
{
    SubdivisionCage cage = voxelCage({Cell{0, 0, 0}});
    for (glm::dvec3& p : cage.positions)
        p = (2.0 * p - 1.0) * halfSize;
    return cage;
}

SubdivisionCage torusCage(int ringSegments, int tubeSegments, double majorRadius, double minorRadius)
{
    if (ringSegments < 3 || tubeSegments < 3)
        throw std::invalid_argument("torus cage: " + std::to_string(ringSegments) + "x" + std::to_string(tubeSegments) +
                                    " segments; use at least 3 in each direction");
    if (!(minorRadius > 0.0 && minorRadius < majorRadius))
        throw std::invalid_argument("torus cage: radii must satisfy 0 < minor radius < major radius");
    SubdivisionCage cage;
    const double twoPi = 2.0 * std::numbers::pi;
    for (int i = 0; i < ringSegments; ++i) {
        const double phi = twoPi * i / ringSegments;
        for (int j = 0; j < tubeSegments; ++j) {
            const double theta = twoPi * j / tubeSegments;
            const double r = majorRadius + minorRadius * std::cos(theta);
            cage.positions.emplace_back(r * std::cos(phi), r * std::sin(phi), minorRadius * std::sin(theta));
        }
    }
    const auto id = [&](int i, int j) { return std::uint32_t((i % ringSegments) * tubeSegments + (j % tubeSegments)); };
    // Going +phi then +theta is counter-clockwise seen from outside the tube.
    for (int i = 0; i < ringSegments; ++i)
        for (int j = 0; j < tubeSegments; ++j)
            addFace(cage, {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    return cage;
}

SubdivisionCage tShapeCage()
{
    return voxelCage({Cell{0, 0, 0}, Cell{1, 0, 0}, Cell{2, 0, 0}, Cell{1, -1, 0}, Cell{1, -2, 0}});
}

SubdivisionCage tetrahedronCage()
{
    SubdivisionCage cage;
    cage.scheme = SubdivisionScheme::Loop;
    cage.positions = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    addFace(cage, {0, 2, 3});
    addFace(cage, {0, 3, 1});
    addFace(cage, {0, 1, 2});
    addFace(cage, {1, 3, 2});
    return cage;
}

SubdivisionCage octahedronCage()
{
    SubdivisionCage cage;
    cage.scheme = SubdivisionScheme::Loop;
    // 0:+x 1:-x 2:+y 3:-y 4:+z 5:-z
    cage.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    addFace(cage, {0, 2, 4});
    addFace(cage, {2, 1, 4});
    addFace(cage, {1, 3, 4});
    addFace(cage, {3, 0, 4});
    addFace(cage, {2, 0, 5});
    addFace(cage, {1, 2, 5});
    addFace(cage, {3, 1, 5});
    addFace(cage, {0, 3, 5});
    return cage;
}

std::vector<std::string> builtInCageNames()
{
    return {"cube", "torus", "t-shape", "tetrahedron", "octahedron"};
}

SubdivisionCage builtInCage(const std::string& name)
{
    if (name == "cube")
        return cubeCage();
    if (name == "torus")
        return torusCage();
    if (name == "t-shape")
        return tShapeCage();
    if (name == "tetrahedron")
        return tetrahedronCage();
    if (name == "octahedron")
        return octahedronCage();
    throw std::invalid_argument("no built-in cage '" + name + "'; use cube, torus, t-shape, tetrahedron or octahedron");
}

} // namespace trimlab
