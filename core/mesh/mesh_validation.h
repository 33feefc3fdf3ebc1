#pragma once
/// \file
/// What is wrong with a triangle mesh, computed directly from its index buffer (sorted
/// edge lists and union-find), so that non-manifold input, which OpenMesh cannot
/// represent, is analysed too. The report decides whether the trim modes are available:
/// the winding index is defined only for closed, consistently oriented surfaces.

#include "core/mesh/triangle_mesh.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace trimlab {

/// How often one defect occurs, with the first few occurrences (in ascending order of
/// vertex, face or edge index) so that messages can name them.
template <class T>
struct DefectSamples {
    static constexpr std::size_t kMaxSamples = 5;

    std::size_t count = 0;
    std::vector<T> first;

    [[nodiscard]] bool any() const { return count > 0; }
    void add(const T& item)
    {
        if (first.size() < kMaxSamples)
            first.push_back(item);
        ++count;
    }
};

/// An undirected edge between vertices a < b and how many triangle sides run along it in
/// each direction (a→b and b→a).
struct MeshEdge {
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    std::uint32_t forward = 0;  ///< uses a → b
    std::uint32_t backward = 0; ///< uses b → a

    [[nodiscard]] std::uint32_t uses() const { return forward + backward; }
};

/// The findings of validateMesh. Faces with an out-of-range index are counted and left
/// out of every other statistic; everything else includes all faces.
struct MeshValidationReport {
    std::size_t vertexCount = 0;
    std::size_t triangleCount = 0;
    std::size_t edgeCount = 0;      ///< distinct undirected edges (self-loops of degenerate faces excluded)
    std::size_t componentCount = 0; ///< face-connected pieces (faces sharing a vertex are connected)
    Bounds bounds;                  ///< of the finite vertices

    DefectSamples<std::size_t> outOfRangeFaces;        ///< faces with an index ≥ #V
    DefectSamples<std::uint32_t> nonFiniteVertices;    ///< NaN or infinite coordinates
    DefectSamples<std::size_t> degenerateFaces;        ///< a repeated index or zero area
    DefectSamples<std::uint32_t> unreferencedVertices; ///< used by no valid face
    DefectSamples<MeshEdge> boundaryEdges;             ///< used by exactly one face
    DefectSamples<MeshEdge> nonManifoldEdges;          ///< used by more than two faces
    DefectSamples<MeshEdge> inconsistentEdges;         ///< two faces, both in the same direction
    DefectSamples<MeshEdge> unbalancedEdges;           ///< used more often in one direction than the other
    DefectSamples<std::uint32_t> nonManifoldVertices;  ///< faces around it form more than one fan

    /// V − E + F over referenced vertices and valid faces; set only for closed manifolds.
    std::optional<std::int64_t> eulerCharacteristic;
    /// Σ genus over components (χ = Σ(2 − 2g)); set only for closed, consistently
    /// oriented manifolds.
    std::optional<std::int64_t> genus;
    /// Σ det(a, b, c) / 6 over finite valid faces, relative to the bounds centre. Positive
    /// for a closed mesh whose normals point outward; only meaningful when closed.
    double signedVolume = 0.0;

    /// No boundary edges and no out-of-range faces (there are triangles).
    [[nodiscard]] bool closed() const;
    /// No non-manifold edges or vertices.
    [[nodiscard]] bool manifold() const;
    /// True iff the winding number is well defined: the mesh is a closed, oriented
    /// 2-cycle — every undirected edge is used equally often in each direction (this
    /// admits non-manifold but consistently oriented meshes, such as two cubes sharing an
    /// edge) — and it has triangles, finite coordinates and in-range indices only.
    [[nodiscard]] bool trimmable() const;
    /// "" when trimmable(); otherwise one or two sentences naming the first problem, its
    /// count and first instance, and what to do, e.g. "Trimming needs a closed surface:
    /// 19 boundary edges (first between vertices 812 and 813). Close the holes (Edit ▸
    /// Close Holes, --close-holes, or a mesh editor) to use the trim modes."
    [[nodiscard]] std::string trimUnavailableReason() const;
};

/// Analyses `mesh` (any index buffer: out-of-range indices, NaN positions and
/// non-manifold configurations are reported, never trusted). O(F log F) time.
/// A vertex is non-manifold when its faces, joined across edges used by exactly two
/// faces, form more than one fan; vertices on non-manifold edges therefore count too.
[[nodiscard]] MeshValidationReport validateMesh(const TriangleMesh& mesh);

/// Why `mesh` bounds nothing that could be drawn or trimmed, or "" when it does: a
/// non-finite position ("vertex 3 is not finite"), or every triangle of zero area ("the
/// geometry is degenerate: all 2 triangles have zero area (the vertices lie on one line or
/// point)"). A few degenerate triangles among others are normal and pass. Loaders and
/// surface tessellation refuse such a mesh at load, naming the file.
[[nodiscard]] std::string unusableGeometryReason(const TriangleMesh& mesh);

/// The multi-line text `trimlab info FILE` prints: `name`, counts, bounding box,
/// components, Euler characteristic and genus, signed volume, every defect with its
/// count and first elements, and a last line "trim modes: available" or
/// "trim modes: unavailable — <reason>". Ends with a newline.
[[nodiscard]] std::string formatReport(const MeshValidationReport& report, const std::string& name);

} // namespace trimlab
