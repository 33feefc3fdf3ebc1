#pragma once
// Small hand-made meshes and labelings shared by the animation tests.
#include "core/animation/mesh_animation.h"
#include "core/animation/vertex_graph.h"

#include <algorithm>
#include <vector>

namespace trimlab::test {

// A 1-unit-high strip of `columns` − 1 unit quads along x: vertex c (bottom row) is at
// (c, 0, 0), vertex columns + c (top row) at (c, 1, 0); quad c is split into
// (c, c+1, columns+c+1) and (c, columns+c+1, columns+c), counter-clockwise seen from +z.
inline TriangleMesh stripMesh(unsigned columns)
{
    TriangleMesh mesh;
    for (unsigned row = 0; row < 2; ++row)
        for (unsigned c = 0; c < columns; ++c)
            mesh.positions.emplace_back(float(c), float(row), 0.0f);
    for (unsigned c = 0; c + 1 < columns; ++c) {
        mesh.triangles.emplace_back(c, c + 1, columns + c + 1);
        mesh.triangles.emplace_back(c, columns + c + 1, columns + c);
    }
    return mesh;
}

// Per-vertex labels of a strip from one label per column (both rows get it).
inline VertexLabeling columnLabels(const std::vector<std::uint32_t>& perColumn)
{
    VertexLabeling labeling;
    for (int row = 0; row < 2; ++row)
        labeling.labels.insert(labeling.labels.end(), perColumn.begin(), perColumn.end());
    labeling.count = perColumn.empty() ? 0 : *std::max_element(perColumn.begin(), perColumn.end()) + 1;
    return labeling;
}

inline MeshAnimation animationOf(const TriangleMesh& rest, std::vector<std::vector<glm::vec3>> poses)
{
    MeshAnimation animation;
    animation.triangles = rest.triangles;
    animation.poses.push_back(rest.positions);
    for (auto& pose : poses)
        animation.poses.push_back(std::move(pose));
    return animation;
}

} // namespace trimlab::test
