#include "core/deform/brush_topology.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace trimlab::deform {

namespace {

// The distinct corners of `t`, in corner order: a triangle that repeats an index (a
// degenerate sliver some files contain) is incident to that vertex once, not twice.
int distinctCorners(const glm::uvec3& t, std::uint32_t out[3])
{
    int n = 0;
    for (int i = 0; i < 3; ++i) {
        if (std::find(out, out + n, t[i]) == out + n)
            out[n++] = t[i];
    }
    return n;
}

void requireIndicesInRange(const std::vector<glm::uvec3>& triangles, std::size_t vertexCount)
{
    for (std::size_t f = 0; f < triangles.size(); ++f) {
        const glm::uvec3& t = triangles[f];
        if (t.x >= vertexCount || t.y >= vertexCount || t.z >= vertexCount)
            throw std::invalid_argument("BrushTopology: triangle " + std::to_string(f) +
                                        " has a vertex index out of range (" + std::to_string(vertexCount) +
                                        " vertices)");
    }
}

} // namespace

BrushTopology::BrushTopology(const TriangleMesh& mesh) : m_triangles(mesh.triangles), m_rest(mesh.positions)
{
    const std::size_t vertexCount = mesh.positions.size();
    requireIndicesInRange(m_triangles, vertexCount);

    // Vertex-to-triangle incidence as compressed rows, filled in triangle order so each
    // row is ascending (region_normals relies on that to sum like vertexNormals does).
    m_faceOffsets.assign(vertexCount + 1, 0);
    std::uint32_t corners[3];
    for (const glm::uvec3& t : m_triangles) {
        const int n = distinctCorners(t, corners);
        for (int i = 0; i < n; ++i)
            ++m_faceOffsets[corners[i] + 1];
    }
    for (std::size_t v = 0; v < vertexCount; ++v)
        m_faceOffsets[v + 1] += m_faceOffsets[v];
    m_faces.resize(m_faceOffsets.back());
    std::vector<std::uint32_t> cursor(m_faceOffsets.begin(), m_faceOffsets.end() - 1);
    for (std::uint32_t f = 0; f < m_triangles.size(); ++f) {
        const int n = distinctCorners(m_triangles[f], corners);
        for (int i = 0; i < n; ++i)
            m_faces[cursor[corners[i]]++] = f;
    }

    // One-rings from the incidence: the other corners of every incident triangle.
    m_ringOffsets.assign(vertexCount + 1, 0);
    m_ring.reserve(m_faces.size() + vertexCount);
    std::vector<std::uint32_t> ring;
    for (std::uint32_t v = 0; v < vertexCount; ++v) {
        ring.clear();
        for (const std::uint32_t* f = facesBegin(v); f != facesEnd(v); ++f) {
            for (int i = 0; i < 3; ++i) {
                if (m_triangles[*f][i] != v)
                    ring.push_back(m_triangles[*f][i]);
            }
        }
        std::sort(ring.begin(), ring.end());
        ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
        m_ring.insert(m_ring.end(), ring.begin(), ring.end());
        m_ringOffsets[v + 1] = static_cast<std::uint32_t>(m_ring.size());
    }
}

} // namespace trimlab::deform
