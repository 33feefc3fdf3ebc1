#include "core/skeleton/skeleton_input.h"

#include "core/mesh/mesh_validation.h"
#include "core/mesh/reader_support.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace trimlab {

namespace {

const char* const kWhatToDo = " Skeleton extraction needs one closed, manifold surface";

std::string edgeText(const DefectSamples<MeshEdge>& edges)
{
    const MeshEdge& e = edges.first.front();
    return std::string(edges.count == 1 ? "" : "first ") + "between vertices " + std::to_string(e.a) + " and " +
           std::to_string(e.b);
}

// Vertex counts of the face-connected components (faces sharing a vertex are connected),
// largest first. Only referenced vertices count. Indices must be in range.
std::vector<std::size_t> componentVertexCounts(const TriangleMesh& mesh)
{
    std::vector<std::uint32_t> parent(mesh.positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](std::uint32_t v) {
        while (parent[v] != v)
            v = parent[v] = parent[parent[v]];
        return v;
    };
    std::vector<char> used(mesh.positions.size(), 0);
    for (const glm::uvec3& t : mesh.triangles) {
        for (int c = 0; c < 3; ++c)
            used[t[c]] = 1;
        parent[find(t[0])] = find(t[1]);
        parent[find(t[1])] = find(t[2]);
    }
    std::vector<std::size_t> countPerRoot(mesh.positions.size(), 0);
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v)
        if (used[v])
            ++countPerRoot[find(v)];
    std::vector<std::size_t> counts;
    for (std::size_t c : countPerRoot)
        if (c > 0)
            counts.push_back(c);
    std::sort(counts.rbegin(), counts.rend());
    return counts;
}

std::string componentText(const std::vector<std::size_t>& counts)
{
    std::string list;
    const std::size_t shown = std::min<std::size_t>(counts.size(), 5);
    for (std::size_t i = 0; i < shown; ++i)
        list += (i == 0 ? "" : ", ") + std::to_string(counts[i]);
    if (shown < counts.size())
        list += ", ...";
    return "Skeleton extraction needs one connected surface, but the mesh has " + std::to_string(counts.size()) +
           " components (vertex counts " + list +
           "). Extract the part to rig into its own file (e.g. separate by loose parts in a mesh editor), or join "
           "the parts into one closed surface.";
}

// The message for the first defect of the buffers themselves, or "".
std::string dataDefectText(const MeshValidationReport& r)
{
    if (r.triangleCount == 0)
        return "Skeleton extraction needs a closed surface, but the mesh has no triangles.";
    if (r.outOfRangeFaces.any())
        return "Skeleton extraction needs valid faces: face " + std::to_string(r.outOfRangeFaces.first.front()) +
               " references a vertex that does not exist. Repair or re-export the mesh.";
    if (r.nonFiniteVertices.any())
        return "Skeleton extraction needs finite coordinates: " +
               countNoun(r.nonFiniteVertices.count, "vertex has", "vertices have") +
               " NaN or infinite coordinates (first: vertex " + std::to_string(r.nonFiniteVertices.first.front()) +
               "). Repair or remove them.";
    return {};
}

// The message for the first defect of the surface (holes, non-manifold places), or "".
std::string surfaceDefectText(const MeshValidationReport& r)
{
    if (r.boundaryEdges.any())
        return "Skeleton extraction needs a closed surface, but the mesh is open: " +
               countNoun(r.boundaryEdges.count, "boundary edge", "boundary edges") + " (" + edgeText(r.boundaryEdges) +
               "). Close the holes (Edit ▸ Close Holes, --close-holes, or a mesh editor) and try again.";
    if (r.nonManifoldEdges.any())
        return "Skeleton extraction needs a manifold surface, but " +
               countNoun(r.nonManifoldEdges.count, "edge is", "edges are") + " shared by more than two faces (" +
               edgeText(r.nonManifoldEdges) + ")." + kWhatToDo +
               ": remove the extra faces or split the mesh at that edge.";
    if (r.nonManifoldVertices.any())
        return "Skeleton extraction needs a manifold surface, but " +
               countNoun(r.nonManifoldVertices.count, "vertex joins", "vertices join") +
               " separate fans of faces (first: vertex " + std::to_string(r.nonManifoldVertices.first.front()) + ")." +
               kWhatToDo + ": split the mesh at that vertex or fill the gap.";
    return {};
}

// Faces with a repeated index pass validateMesh's edge checks (their self-loop is
// skipped and their other edge is used once in each direction) but are no triangles.
void checkRepeatedIndices(const TriangleMesh& mesh)
{
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        const glm::uvec3 t = mesh.triangles[f];
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
            throw SkeletonInputError("Skeleton extraction needs proper triangles: face " + std::to_string(f) +
                                     " uses vertex " + std::to_string(t[0] == t[1] || t[0] == t[2] ? t[0] : t[1]) +
                                     " twice. Remove degenerate faces (e.g. merge by distance and clean up in a "
                                     "mesh editor) and try again.");
    }
}

} // namespace

void checkSkeletonInput(const TriangleMesh& mesh)
{
    const MeshValidationReport report = validateMesh(mesh);
    if (std::string text = dataDefectText(report); !text.empty())
        throw SkeletonInputError(text);
    checkRepeatedIndices(mesh);
    if (std::string text = surfaceDefectText(report); !text.empty())
        throw SkeletonInputError(text);
    if (report.componentCount != 1)
        throw SkeletonInputError(componentText(componentVertexCounts(mesh)));
}

} // namespace trimlab
