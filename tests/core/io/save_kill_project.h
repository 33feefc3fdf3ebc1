#pragma once
// The two versions of a big project that tst_save_kill and its helper
// (save_kill_helper.cpp) save over each other: a 160 × 160 grid (25,600 vertices) with
// frames that each move a band of vertices, so one save writes a few MB.
#include "core/timeline/project_file.h"

#include <cstdint>
#include <vector>

namespace trimlab::test {

/// Version 0 has `frames` frames, version 1 one more (and another view), so the two
/// documents differ in size and content.
inline timeline::Timeline saveKillTimeline(int version)
{
    constexpr int n = 160;
    TriangleMesh mesh;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            mesh.positions.emplace_back(float(i) / float(n - 1), float(j) / float(n - 1), 0.0f);
    for (int j = 0; j + 1 < n; ++j) {
        for (int i = 0; i + 1 < n; ++i) {
            const auto v = std::uint32_t(j * n + i);
            mesh.triangles.emplace_back(v, v + 1, v + n + 1);
            mesh.triangles.emplace_back(v, v + n + 1, v + n);
        }
    }
    timeline::Timeline t(std::move(mesh), DynamicRule::Confluent);
    const int frames = 12 + version;
    for (int f = 0; f < frames; ++f) {
        timeline::Frame frame;
        for (std::uint32_t v = std::uint32_t(f) * 997u % 4000u; v < std::uint32_t(n * n); v += 3)
            frame.vertices.push_back(v);
        for (const std::uint32_t v : frame.vertices) {
            const glm::vec3 p = t.currentPositions()[v];
            frame.before.push_back(p);
            frame.after.push_back(p + glm::vec3(0.0f, 0.0f, 0.001f * float(f + 1)));
        }
        frame.stroke.anchor = {0.5, 0.5, 0.0};
        frame.stroke.drag = {0.0, 0.0, 0.01 * (f + 1)};
        if (f == 6)
            t.startSet(DynamicRule::ConstructiveAdditive);
        t.appendFrame(std::move(frame));
    }
    return t;
}

inline timeline::ProjectExtras saveKillExtras(int version)
{
    timeline::ProjectExtras extras;
    extras.view = timeline::ProjectView{};
    extras.view->fovyDegrees = 40.0 + version;
    return extras;
}

} // namespace trimlab::test
