#pragma once
// Small meshes and hand-made frames shared by the timeline tests.
#include "core/timeline/timeline.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

namespace trimlab::test {

/// An n×n vertex grid in the z = 0 plane over [0, 1]², two triangles per cell, with
/// coordinates such as 1/7 that are not exact in binary.
inline TriangleMesh gridMesh(int n = 8)
{
    TriangleMesh mesh;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i)
            mesh.positions.emplace_back(float(i) / float(n - 1), float(j) / float(n - 1), 0.0f);
    }
    for (int j = 0; j + 1 < n; ++j) {
        for (int i = 0; i + 1 < n; ++i) {
            const auto v = std::uint32_t(j * n + i);
            const auto un = std::uint32_t(n);
            mesh.triangles.emplace_back(v, v + 1, v + un + 1);
            mesh.triangles.emplace_back(v, v + un + 1, v + un);
        }
    }
    return mesh;
}

/// A frame moving `vertices` (sorted) of the timeline's current positions to `after`.
inline timeline::Frame frameTo(const timeline::Timeline& t, std::vector<std::uint32_t> vertices,
                               std::vector<glm::vec3> after)
{
    timeline::Frame frame;
    frame.vertices = std::move(vertices);
    // Out-of-range vertices are what some tests hand to appendFrame on purpose; their
    // "before" is a placeholder rather than a read past the positions.
    const std::vector<glm::vec3>& current = t.currentPositions();
    for (const std::uint32_t v : frame.vertices)
        frame.before.push_back(v < current.size() ? current[v] : glm::vec3(0.0f));
    frame.after = std::move(after);
    frame.stroke.anchor = {0.25, 0.5, 0.0};
    frame.stroke.drag = {0.0, 0.0, 0.1};
    return frame;
}

/// A small history for export tests: a 6×6 grid, two sets, a frame that moves a vertex
/// back to its base position, and a frame that moves nothing.
inline timeline::Timeline exportTimeline()
{
    timeline::Timeline t(gridMesh(6), DynamicRule::ConstructiveAdditive);
    t.appendFrame(frameTo(t, {7, 8, 14}, {{0.2f, 0.2f, 0.3f}, {0.4f, 0.2f, 0.25f}, {0.4f, 0.4f, -0.1f}}));
    t.appendFrame(frameTo(t, {8, 20}, {{0.4f, 0.2f, 0.5f}, {0.8f, 0.6f, 1e-7f}}));
    t.startSet(DynamicRule::Confluent);
    t.appendFrame(frameTo(t, {7, 35}, {gridMesh(6).positions[7], {1.0f, 1.0f, -2.5f}}));
    t.appendFrame(frameTo(t, {}, {}));
    t.appendFrame(frameTo(t, {0, 14}, {{-0.1f, -0.1f, 0.05f}, {0.4f, 0.4f, 0.1f}}));
    return t;
}

/// |a − b| <= tolerance · max(1, |b|) componentwise; "" or the first difference.
inline std::string closeTo(std::span<const glm::vec3> actual, std::span<const glm::vec3> expected, double tolerance)
{
    if (actual.size() != expected.size())
        return std::to_string(actual.size()) + " positions instead of " + std::to_string(expected.size());
    for (std::size_t v = 0; v < actual.size(); ++v) {
        for (int c = 0; c < 3; ++c) {
            const double a = actual[v][c];
            const double b = expected[v][c];
            if (!(std::abs(a - b) <= tolerance * std::max(1.0, std::abs(b))))
                return "vertex " + std::to_string(v) + " component " + std::to_string(c) + ": " + std::to_string(a) +
                       " instead of " + std::to_string(b);
        }
    }
    return {};
}

/// Equal bit patterns (-0.0f != 0.0f), which operator== on floats does not check.
inline bool sameBits(std::span<const glm::vec3> a, std::span<const glm::vec3> b)
{
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size_bytes()) == 0);
}

inline bool sameBits(double a, double b)
{
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

inline bool sameBits(const glm::dvec3& a, const glm::dvec3& b)
{
    return sameBits(a.x, b.x) && sameBits(a.y, b.y) && sameBits(a.z, b.z);
}

/// Every float and double of two timelines has the same bits (on top of operator==).
inline bool sameBits(const timeline::Timeline& a, const timeline::Timeline& b)
{
    if (a.frameCount() != b.frameCount() || !sameBits(a.base().positions, b.base().positions))
        return false;
    for (int f = 1; f < a.frameCount(); ++f) {
        const timeline::Frame& fa = a.frame(f);
        const timeline::Frame& fb = b.frame(f);
        const deform::Stroke& sa = fa.stroke;
        const deform::Stroke& sb = fb.stroke;
        if (!sameBits(fa.before, fb.before) || !sameBits(fa.after, fb.after) || !sameBits(sa.anchor, sb.anchor) ||
            !sameBits(sa.drag, sb.drag) || !sameBits(sa.brush.radius, sb.brush.radius) ||
            !sameBits(sa.brush.strength, sb.brush.strength) ||
            !sameBits(sa.brush.smoothingStep, sb.brush.smoothingStep))
            return false;
    }
    return true;
}

} // namespace trimlab::test
