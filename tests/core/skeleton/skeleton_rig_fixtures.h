#pragma once
// Small generated closed meshes with hand-built rigs for the bone-heat, posing and export
// tests: a chain of bones along the y axis (the axis of skeleton_shapes.h's axisCapsule),
// and a T-shaped tube made of voxels (exact inside test, so visibility can be checked
// without the code under test).
#include "core/mesh/triangle_mesh.h"
#include "core/skeleton/skeleton.h"

#include <glm/vec3.hpp>

#include <array>
#include <map>
#include <tuple>
#include <vector>

namespace trimlab::test {

// A chain rig along the y axis: joints at the given heights, root = joint 0, bone b from
// joint b to joint b+1 (parent bone b−1).
inline SkeletonRig chainRig(const std::vector<double>& heights)
{
    SkeletonRig rig;
    for (std::size_t j = 0; j < heights.size(); ++j) {
        rig.joints.emplace_back(0.0, heights[j], 0.0);
        rig.parent.push_back(int(j) - 1);
    }
    rig.root = 0;
    for (std::size_t b = 0; b + 1 < heights.size(); ++b)
        rig.bones.push_back({int(b), int(b) + 1, int(b) - 1});
    return rig;
}

// Boundary surface of a set of unit voxels scaled by `cell`: every face between an
// occupied and an empty cell, as two triangles, counter-clockwise seen from outside;
// corners shared. Closed and manifold for shapes without edge- or corner-only contacts.
inline TriangleMesh voxelSurface(const std::vector<std::array<int, 3>>& cells, double cell)
{
    std::map<std::array<int, 3>, bool> occupied;
    for (const auto& c : cells)
        occupied[c] = true;
    std::map<std::array<int, 3>, unsigned> corners;
    TriangleMesh mesh;
    auto corner = [&](std::array<int, 3> c) {
        const auto [it, added] = corners.try_emplace(c, unsigned(mesh.positions.size()));
        if (added)
            mesh.positions.emplace_back(float(c[0] * cell), float(c[1] * cell), float(c[2] * cell));
        return it->second;
    };
    for (const auto& c : cells)
        for (int axis = 0; axis < 3; ++axis)
            for (const int side : {-1, 1}) {
                std::array<int, 3> n = c;
                n[std::size_t(axis)] += side;
                if (occupied.count(n))
                    continue;
                const std::size_t u = std::size_t(axis + 1) % 3, v = std::size_t(axis + 2) % 3;
                std::array<int, 3> base = c;
                base[std::size_t(axis)] += side > 0 ? 1 : 0;
                std::array<int, 3> bu = base, buv = base, bv = base;
                bu[u] += 1;
                buv[u] += 1;
                buv[v] += 1;
                bv[v] += 1;
                std::array<unsigned, 4> q = {corner(base), corner(bu), corner(buv), corner(bv)};
                if (side < 0)
                    std::swap(q[1], q[3]); // e_u × e_v = e_axis points inward on the − side
                mesh.triangles.emplace_back(q[0], q[1], q[2]);
                mesh.triangles.emplace_back(q[0], q[2], q[3]);
            }
    return mesh;
}

// The T: a bar x ∈ [−6, 6], y ∈ [0, 2], z ∈ [0, 2] and a stem x ∈ [−1, 1], y ∈ [−6, 0],
// z ∈ [0, 2], voxels of 0.25.
constexpr double kTCell = 0.25;

inline bool insideT(const glm::dvec3& p)
{
    const bool bar = p.x > -6 && p.x < 6 && p.y > 0 && p.y < 2 && p.z > 0 && p.z < 2;
    const bool stem = p.x > -1 && p.x < 1 && p.y > -6 && p.y <= 0 && p.z > 0 && p.z < 2;
    return bar || stem;
}

inline TriangleMesh makeTTube()
{
    std::vector<std::array<int, 3>> cells;
    for (int x = -24; x < 24; ++x)
        for (int y = -24; y < 8; ++y)
            for (int z = 0; z < 8; ++z) {
                const glm::dvec3 centre((x + 0.5) * kTCell, (y + 0.5) * kTCell, (z + 0.5) * kTCell);
                if (insideT(centre))
                    cells.push_back({x, y, z});
            }
    return voxelSurface(cells, kTCell);
}

// Bones of the T rig: 0 left arm, 1 right arm, 2 stem; all start at the junction (joint 0).
inline SkeletonRig tRig()
{
    SkeletonRig rig;
    rig.joints = {{0.0, 1.0, 1.0}, {-5.5, 1.0, 1.0}, {5.5, 1.0, 1.0}, {0.0, -5.5, 1.0}};
    rig.parent = {-1, 0, 0, 0};
    rig.root = 0;
    rig.bones = {{0, 1, -1}, {0, 2, -1}, {0, 3, -1}};
    return rig;
}

} // namespace trimlab::test
