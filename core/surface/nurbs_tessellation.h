#pragma once
/// \file
/// A NURBS surface tessellated into a triangle mesh of fixed connectivity, and the fast
/// re-evaluation that keeps it in step while the designer moves control points (thesis
/// 8.2: the trim rules, static and dynamic, run on this mesh every frame).
///
/// Sampling. Each direction is sampled at parameters t_0 < … < t_m covering its domain:
/// every distinct knot is a sample (so creases at repeated knots and the rims of the
/// capped tube stay sharp), and each non-empty knot span [a, b] is split into
/// max(m, round(segments · (b − a) / domainLength)) equal intervals, m = 1 in an open
/// direction and ceil(3 / #spans) in a closed one (tessellationParameters in
/// nurbs_sampling.h). So the counts follow `segments` when it is a multiple of the number
/// of equal spans (the sphere's and torus's circles have 4, the capped tube's profile 3)
/// and are otherwise rounded per span. parametersU() and parametersV() return the result
/// (m+1 values each, the domain ends included).
///
/// Valid but degenerate surfaces (regions collapsed by edits) tessellate without NaN:
/// coincident vertices give zero-area triangles (kept: the connectivity is fixed) and
/// normals fall back as described below, never a crash.
///
/// Vertices. Sample (a, b) (a along u, b along v) becomes a vertex, except that
///  - in a closed direction the last sample line is the first (the seam shares vertices:
///    there is no duplicate vertex at u_begin and u_end), and
///  - all samples of a pole side (isPole) are one vertex.
/// Triangles. Every grid cell (a, b)–(a+1, b+1) gives the triangles (00, 10, 11) and
/// (00, 11, 01) where (x, y) means sample (a+x, b+y); a triangle that repeats a vertex
/// (cells touching a pole) is left out, so poles become triangle fans. Triangles are
/// counter-clockwise around Su × Sv. Consequently, with cu/cv = number of intervals:
///  - sphere, capped tube (closedU, 2 poles): #V = cu·(cv−1) + 2, #F = 2·cu·(cv−1);
///  - torus (closed both ways):               #V = cu·cv,        #F = 2·cu·cv;
///  - cylinder (closedU, open v):             #V = cu·(cv+1),    #F = 2·cu·cv;
///  - patch (open):                           #V = (cu+1)(cv+1), #F = 2·cu·cv.
/// The closed primitives give closed, manifold, consistently oriented meshes with
/// positive signed volume (tests/core/surface/tst_nurbs_tessellation.cpp checks it).
///
/// Fast re-evaluation. The constructor runs the span search and the basis recursion once
/// per sample parameter and keeps a sparse table in tensor-product form: for each u
/// sample the first control column of its span and the p+1 values N_i(u) and N'_i(u),
/// likewise for each v sample (q+1 values). Sample (a, b) depends on the (p+1)(q+1)
/// control points of its spans, with weights N_i(u_a)N_j(v_b), N'_i(u_a)N_j(v_b) and
/// N_i(u_a)N'_j(v_b); the table stores the factors, not the products, so it takes
/// O((#u + #v)(p+1)) memory instead of O(#u·#v·(p+1)(q+1)). After control points or
/// weights change, update() recomputes positions and derivatives as sparse mat-vecs over
/// the homogeneous control points (w·P, w) — first Σ_i N_i(u_a)(w·P, w)_ij for every u
/// sample and control row, then Σ_j over the q+1 rows of each sample — and applies the
/// rational quotient rule: no span search, no basis recursion. update(surface, changed)
/// recomputes only the samples whose spans include a changed control point, summing in
/// the same order, so its results are bitwise equal to a full update() and to
/// evaluateNurbs at the same parameters. Positions are computed in double
/// (positionsDouble()) and rounded to float once for mesh().
///
/// Normals. Unit Su × Sv per vertex. At a pole vertex, where Su × Sv vanishes, the normal
/// is the limit: the tangent plane is spanned by the derivatives across the pole side
/// at all its samples, so n = Σ_k d_k × d_{k+1} (Newell's sum over consecutive samples),
/// oriented like the normals of the next sample line. Any other vertex without a normal
/// (a degenerate point of an edited surface) gets the normalised sum of the unit normals
/// of its incident triangles, or (0, 0, 0) when those are degenerate too — never NaN.

#include "core/mesh/triangle_mesh.h"
#include "core/surface/nurbs_surface.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

/// Most intervals per direction, and most samples in all, a tessellation accepts.
inline constexpr int kMaxTessellationSegments = 8192;
inline constexpr std::size_t kMaxTessellationSamples = std::size_t(16) << 20;

class NurbsTessellation {
public:
    /// An empty tessellation (no vertices); assign a constructed one.
    NurbsTessellation() = default;

    /// Samples `surface` with about `segmentsU` × `segmentsV` intervals (see the file
    /// comment), builds the fixed connectivity, the sparse tables and the first positions
    /// and normals. Throws std::invalid_argument when the surface is invalid
    /// (requireValidNurbs), a segment count is < 1 or > kMaxTessellationSegments, or the
    /// sample count exceeds kMaxTessellationSamples.
    NurbsTessellation(const NurbsSurface& surface, int segmentsU, int segmentsV);

    /// The mesh: float positions and the fixed triangles (see the file comment).
    [[nodiscard]] const TriangleMesh& mesh() const { return m_mesh; }
    /// #V unit normals (see the file comment), float.
    [[nodiscard]] const std::vector<glm::vec3>& normals() const { return m_normals; }
    /// #V positions in double precision (mesh().positions are these rounded to float).
    [[nodiscard]] const std::vector<glm::dvec3>& positionsDouble() const { return m_positions; }

    /// Sample parameters of each direction (domain ends included).
    [[nodiscard]] const std::vector<double>& parametersU() const { return m_parametersU; }
    [[nodiscard]] const std::vector<double>& parametersV() const { return m_parametersV; }
    /// The vertex of sample (a, b), 0 <= a < parametersU().size(), 0 <= b <
    /// parametersV().size() (no range check).
    [[nodiscard]] std::uint32_t vertexOfSample(std::size_t a, std::size_t b) const
    {
        return m_sampleVertex[b * m_parametersU.size() + a];
    }
    /// The (u, v) parameters the position of `vertex` is evaluated at (for a pole vertex,
    /// the first of its samples).
    [[nodiscard]] glm::dvec2 vertexParameters(std::uint32_t vertex) const;
    /// True when `vertex` is a pole vertex.
    [[nodiscard]] bool isPoleVertex(std::uint32_t vertex) const;

    /// True when `surface` has the degrees, counts, knots, closed flags and poles this
    /// tessellation was built for, so that update() may be called with it.
    [[nodiscard]] bool matches(const NurbsSurface& surface) const;

    /// Recomputes every position and normal from the control points and weights of
    /// `surface` (sparse mat-vec). Throws std::invalid_argument unless matches(surface),
    /// or when a position/weight is not finite, a weight <= 0, or a tie is broken (a seam
    /// twin or a pole point moved alone: use moveControlPoint). On a throw nothing changes.
    void update(const NurbsSurface& surface);

    /// Recomputes only what depends on the control points `changed` (and the points
    /// linked to them) and returns the vertices whose position depends on them — the
    /// union of support() — sorted ascending. Positions and normals of all other vertices
    /// are untouched (bitwise); normals are recomputed for every vertex whose samples'
    /// spans include a changed point (a slightly larger set than the moved vertices, as
    /// derivatives reach further than values), and for poles whose samples do. Only the
    /// control points in `changed` and their linked points are re-read from `surface`:
    /// the caller lists every point it changed. (A vertex whose normal came from the
    /// triangle fallback, see the file comment, is refreshed only when it is recomputed.)
    /// When the changed points reach most samples, the separable full pass runs instead;
    /// the results are the same bits either way. Same throws as update(), plus std::out_of_range for an
    /// index >= controlPointCount().
    std::vector<std::uint32_t> update(const NurbsSurface& surface, std::span<const std::size_t> changed);

    /// The vertices whose position has a non-zero weight N_i(u)N_j(v) for control point
    /// `controlIndex` or for a point linked to it (those move together), sorted ascending:
    /// exactly the vertices that move when that control point moves. std::out_of_range
    /// for a bad index.
    [[nodiscard]] std::vector<std::uint32_t> support(std::size_t controlIndex) const;

    [[nodiscard]] std::size_t controlPointCount() const { return m_controlCount; }
    [[nodiscard]] std::size_t sampleCount() const { return m_parametersU.size() * m_parametersV.size(); }
    /// Bytes held by the sparse tables (for benchmarks).
    [[nodiscard]] std::size_t tableBytes() const;

private:
    // Per-direction sparse basis table: for each sample parameter the first control
    // index of its span and the degree+1 basis values and derivatives there; for each
    // control index the contiguous range of samples whose span includes it.
    struct DirectionTable {
        std::size_t width = 0;                             // degree + 1
        std::vector<std::uint32_t> first;                  // per sample
        std::vector<double> basis, derivative;             // per sample × width
        std::vector<std::uint32_t> sampleBegin, sampleEnd; // per control index
    };
    // A pole vertex and the samples merged into it, in order along the side.
    struct Pole {
        std::uint32_t vertex = 0;
        bool alongU = true; // the side runs along u (VBegin/VEnd): the cross derivative is ∂/∂v
        std::vector<std::size_t> samples;
    };

    void buildBasisTables();
    void buildTopology();
    void buildTriangles();
    void buildPoles();
    void requireUpdatable(const NurbsSurface& surface) const;
    void loadHomogeneous(const NurbsSurface& surface);
    void evaluateAll();
    void evaluateSample(std::size_t sample);
    void storeSample(std::size_t sample, const glm::dvec4& a, const glm::dvec4& au, const glm::dvec4& av);
    void updateNormal(std::uint32_t vertex);
    [[nodiscard]] glm::dvec3 poleNormal(const Pole& pole) const;
    [[nodiscard]] glm::dvec3 fanNormal(std::uint32_t vertex, bool unitFaces) const;
    [[nodiscard]] std::vector<std::size_t> tiedGroup(std::span<const std::size_t> changed) const;
    [[nodiscard]] std::vector<std::uint32_t> supportOf(std::span<const std::size_t> group) const;

    NurbsSurface m_shape;                          // the surface built from (for shape checks and ties)
    bool m_pole[4] = {false, false, false, false}; // indexed by NurbsSide
    std::size_t m_controlCount = 0;
    std::vector<double> m_parametersU, m_parametersV;
    DirectionTable m_tableU, m_tableV;

    std::vector<std::uint32_t> m_sampleVertex; // sample b·#U + a → vertex
    std::vector<std::size_t> m_vertexSample;   // vertex → representative sample
    std::vector<std::uint8_t> m_vertexIsPole;
    std::vector<Pole> m_poles;
    std::vector<std::uint32_t> m_triangleStart, m_vertexTriangles; // vertex → triangles (CSR)

    std::vector<glm::dvec4> m_homogeneous;          // (w·P, w) per control point
    std::vector<glm::dvec4> m_rowSums, m_rowSumsDu; // scratch of evaluateAll
    std::vector<glm::dvec3> m_sampleDu, m_sampleDv; // per sample
    std::vector<std::uint8_t> m_sampleMark;         // scratch of update(changed)
    double m_derivativeFloor = 0.0;
    std::vector<glm::dvec3> m_positions; // per vertex
    std::vector<glm::vec3> m_normals;    // per vertex
    TriangleMesh m_mesh;
};

} // namespace trimlab
