#pragma once
/// \file
/// Connectivity the brush needs, built once per mesh topology (positions may change
/// freely afterwards): vertex one-rings, vertex-to-triangle incidence and edges.

#include "core/mesh/triangle_mesh.h"

#include <cstdint>
#include <vector>

namespace trimlab::deform {

class BrushTopology {
public:
    explicit BrushTopology(const TriangleMesh& mesh);

    [[nodiscard]] std::size_t vertexCount() const { return m_ringOffsets.size() - 1; }
    [[nodiscard]] const std::vector<glm::uvec3>& triangles() const { return m_triangles; }
    /// The positions of the mesh it was built from: the rest surface (a history's base
    /// mesh), on which a stroke's region is measured too (brush_stroke.h).
    [[nodiscard]] const std::vector<glm::vec3>& restPositions() const { return m_rest; }
    /// Neighbours of vertex v (sorted, unique): ring(v) = [ringBegin(v), ringEnd(v)).
    [[nodiscard]] const std::uint32_t* ringBegin(std::uint32_t v) const { return m_ring.data() + m_ringOffsets[v]; }
    [[nodiscard]] const std::uint32_t* ringEnd(std::uint32_t v) const { return m_ring.data() + m_ringOffsets[v + 1]; }
    /// Triangles incident to vertex v.
    [[nodiscard]] const std::uint32_t* facesBegin(std::uint32_t v) const { return m_faces.data() + m_faceOffsets[v]; }
    [[nodiscard]] const std::uint32_t* facesEnd(std::uint32_t v) const { return m_faces.data() + m_faceOffsets[v + 1]; }

private:
    std::vector<glm::uvec3> m_triangles;
    std::vector<glm::vec3> m_rest;
    std::vector<std::uint32_t> m_ringOffsets, m_ring;
    std::vector<std::uint32_t> m_faceOffsets, m_faces;
};

} // namespace trimlab::deform
