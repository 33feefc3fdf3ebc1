#pragma once
/// \file
/// A subdivision surface tessellated into a trimmable triangle mesh of fixed
/// connectivity (thesis 8.2): OpenSubdiv refines the cage topology once, stencil tables
/// express every output vertex (and, in limit mode, its two tangents) as a weighted sum of
/// cage vertices, and each edit of the cage only re-applies those sums — no refinement,
/// no patch evaluation per edit. Nothing geometric (self-intersections) is computed, so
/// the trim modes can re-run on every frame.

#include "core/mesh/triangle_mesh.h"
#include "core/surface/subdivision_cage.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

/// Where output vertices come from.
enum class SubdivisionMode {
    /// The vertices of the cage refined `level` times (OpenSubdiv uniform refinement,
    /// Far::StencilTable); normals are the mesh's angle-weighted vertex normals.
    Uniform,
    /// The same vertex set and connectivity, each vertex pushed to its point on the limit
    /// surface (Far::LimitStencilTable over a feature-adaptive PatchTable); normals are
    /// normalize(∂P/∂u × ∂P/∂v) from the limit tangents.
    Limit,
};

/// What to build. `level` in [0, SubdivisionSurface::kMaxLevel].
struct SubdivisionSettings {
    int level = 3;
    SubdivisionMode mode = SubdivisionMode::Limit;
};

/// A point of the limit surface in OpenSubdiv's ptex parameterization: `ptexFace` is a
/// Far::PtexIndices face (one per cage quad for Catmull–Clark and per triangle for Loop;
/// an n-gon with n ≠ 4 under Catmull–Clark has n ptex faces, one per corner, numbered
/// in corner order), (u, v) ∈ [0,1]² (Loop: u + v ≤ 1), u running from the face's first
/// corner along its first edge, v along its last edge.
struct LimitLocation {
    std::uint32_t ptexFace = 0;
    double u = 0.0;
    double v = 0.0;
};

/// One output vertex as a weighted sum of cage vertices (weights sum to 1 for positions,
/// to 0 for tangents). Only non-zero weights are stored.
struct StencilWeight {
    std::uint32_t cageVertex = 0;
    double weight = 0.0;
};

/// A cage subdivided into a fixed-connectivity triangle mesh, re-evaluated per edit.
///
/// Build once per (cage topology, scheme, sharpness tags, level, mode); then call
/// evaluate() or update() with new cage positions (same #V) as often as needed. The mesh
/// connectivity never changes after construction.
///
/// Output vertices: those of the cage refined `level` times, in the order of Far's
/// uniform refinement with default options (the vertices of TopologyRefiner level
/// `level`); level 0 keeps the cage vertices in cage order. Output triangles: each refined
/// face split into triangles — a quad (a,b,c,d) into (a,b,c) and (a,c,d), an n-gon of a
/// level-0 Catmull–Clark cage into a fan from its first corner — oriented like the cage
/// faces, so a closed, consistently oriented manifold cage gives a closed, consistently
/// oriented manifold mesh (outward if the cage faces point outward).
///
/// Counts: Catmull–Clark quads 4^L per cage quad (an n-gon gives n·4^(L−1) for L ≥ 1);
/// Loop 4^L triangles per cage triangle.
class SubdivisionSurface {
public:
    /// The deepest uniform level accepted (UI slider range 0..kMaxLevel).
    static constexpr int kMaxLevel = 5;
    /// The most output triangles accepted; larger requests are refused before any work.
    static constexpr std::size_t kMaxTriangles = std::size_t(8) << 20;
    /// The isolation level of the feature-adaptive refinement behind limit mode (patches
    /// around extraordinary vertices and semi-sharp features are isolated this deep, then
    /// Gregory-basis end caps close them). Independent checks must use the same value.
    static constexpr int kLimitIsolationLevel = 4;

    /// Validates `cage` (validateCage), refines its topology, builds the stencil tables
    /// and evaluates the surface at `cage.positions`.
    /// Throws SubdivisionError for an invalid cage, a level outside [0, kMaxLevel]
    /// ("subdivision level 6 is outside 0 to 5"), a result above kMaxTriangles, or a
    /// topology OpenSubdiv refuses.
    SubdivisionSurface(const SubdivisionCage& cage, SubdivisionSettings settings);

    [[nodiscard]] const SubdivisionSettings& settings() const { return m_settings; }
    [[nodiscard]] SubdivisionScheme scheme() const { return m_scheme; }
    /// #V of the cage this surface was built for; evaluate() requires exactly this many.
    [[nodiscard]] std::size_t cageVertexCount() const { return m_cageVertexCount; }

    /// The output mesh: positions (float copies of positions()) and the fixed triangles.
    [[nodiscard]] const TriangleMesh& mesh() const { return m_mesh; }
    /// #V_out×3 output positions in double precision (what the stencils produced).
    [[nodiscard]] const std::vector<glm::dvec3>& positions() const { return m_positions; }
    /// #V_out×3 unit normals pointing to the side the cage faces point to. Where the limit
    /// tangents are degenerate (parallel or zero) the mesh's vertex normal is used; a
    /// vertex of a degenerate mesh region gets (0,0,0), never NaN.
    [[nodiscard]] const std::vector<glm::vec3>& normals() const { return m_normals; }
    /// Limit mode: #V_out×3 tangents ∂P/∂u and ∂P/∂v at limitLocations(); empty in
    /// uniform mode.
    [[nodiscard]] const std::vector<glm::dvec3>& tangentsU() const { return m_tangentsU; }
    [[nodiscard]] const std::vector<glm::dvec3>& tangentsV() const { return m_tangentsV; }
    /// Limit mode: the (ptex face, u, v) of each output vertex; empty in uniform mode.
    [[nodiscard]] const std::vector<LimitLocation>& limitLocations() const { return m_locations; }

    /// Re-evaluates every output position and normal for new cage positions (#V×3,
    /// #V = cageVertexCount(); throws std::invalid_argument otherwise, and for
    /// non-finite positions). Cost: one pass over the stencil tables.
    void evaluate(std::span<const glm::dvec3> cagePositions);

    /// Like evaluate() after only the cage vertices `movedCageVertices` changed (the other
    /// entries of `cagePositions` must equal the previous call's): only the output vertices
    /// in their supports are recomputed, with their normals (uniform mode also recomputes
    /// the normals of their one-ring, which a moved vertex turns too). Returns those
    /// output vertices, sorted and unique — the sparse set an edit stores. Throws like evaluate(), and for a moved
    /// index ≥ cageVertexCount().
    std::vector<std::uint32_t> update(std::span<const glm::dvec3> cagePositions,
                                      std::span<const std::uint32_t> movedCageVertices);

    /// The output vertices whose position has a non-zero stencil weight for `cageVertex`
    /// (sorted ascending): exactly the vertices that move when it moves. Empty for an
    /// index ≥ cageVertexCount().
    [[nodiscard]] std::span<const std::uint32_t> support(std::uint32_t cageVertex) const;

    /// The position stencil of output vertex `v` (v < #V_out): non-zero weights only,
    /// sorted by cage vertex.
    [[nodiscard]] std::span<const StencilWeight> positionStencil(std::uint32_t v) const;

    /// Total stored stencil entries (positions + tangents), for memory reports.
    [[nodiscard]] std::size_t stencilEntryCount() const;

    /// Stencils in compressed rows: output vertex v uses entries [offsets[v], offsets[v+1]).
    /// Public so that tests and the builder can fill and read them directly.
    struct StencilRows {
        std::vector<std::size_t> offsets{0};
        std::vector<StencilWeight> entries;
    };

private:
    void requireCage(std::span<const glm::dvec3> cagePositions) const;
    void applyStencils(std::span<const glm::dvec3> cage, std::span<const std::uint32_t> vertices);
    void updateNormals(std::span<const std::uint32_t> vertices);
    void buildSupport();
    void buildVertexTriangles();
    [[nodiscard]] glm::vec3 angleWeightedNormal(std::uint32_t v) const;

    SubdivisionSettings m_settings;
    SubdivisionScheme m_scheme = SubdivisionScheme::CatmullClark;
    std::size_t m_cageVertexCount = 0;
    StencilRows m_position;
    StencilRows m_tangentU;                    // limit mode only
    StencilRows m_tangentV;                    // limit mode only
    std::vector<std::size_t> m_supportOffsets; // cage vertex c: m_support[offsets[c] .. offsets[c+1])
    std::vector<std::uint32_t> m_support;
    std::vector<std::size_t> m_vertexTriangleOffsets; // uniform mode: triangles around each output vertex
    std::vector<std::uint32_t> m_vertexTriangles;     // (ascending, as vertexNormals sums them)
    std::vector<LimitLocation> m_locations;
    TriangleMesh m_mesh;
    std::vector<glm::dvec3> m_positions;
    std::vector<glm::dvec3> m_tangentsU;
    std::vector<glm::dvec3> m_tangentsV;
    std::vector<glm::vec3> m_normals;
};

} // namespace trimlab
