#pragma once
/// \file
/// The control cage of a subdivision surface (thesis 8.2: the designer edits control
/// points, the surface is re-subdivided every frame): polygon faces kept as polygons,
/// the scheme, and OpenSubdiv's sharpness tags (creases on edges, corners on vertices).
/// Connectivity and positions are separate fields so that an edit replaces positions only.

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace trimlab {

/// Which subdivision rules refine the cage (OpenSubdiv's Sdc::SchemeType).
enum class SubdivisionScheme {
    CatmullClark, ///< any polygons; refined faces are quads (Sdc::SCHEME_CATMARK)
    Loop,         ///< triangles only; refined faces are triangles (Sdc::SCHEME_LOOP)
};

/// How boundary vertices behave (OpenSubdiv's Sdc::Options::VtxBoundaryInterpolation).
/// Matters only for open cages; the built-in cages are closed.
enum class BoundaryInterpolation {
    EdgesOnly,       ///< boundary edges are sharp, corners (valence-2 boundary vertices) smooth
    EdgesAndCorners, ///< boundary edges sharp and valence-2 boundary vertices kept as corners
};

/// OpenSubdiv's "infinitely sharp" value (Sdc::Crease::SHARPNESS_INFINITE): a crease or
/// corner at least this sharp is kept exactly at every level and on the limit surface.
inline constexpr float kInfiniteSharpness = 10.0f;

/// A sharp cage edge between vertices `a` and `b` (either order; the edge must exist in
/// some face). `sharpness` ≥ 0: 0 is smooth, k sharpens the first k levels (fractional
/// values blend), ≥ kInfiniteSharpness is sharp for ever (a C0 crease on the limit).
struct CageCrease {
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    float sharpness = kInfiniteSharpness;
};

/// A sharp cage vertex (OpenSubdiv's vertex sharpness); `sharpness` as for CageCrease.
struct CageCorner {
    std::uint32_t vertex = 0;
    float sharpness = kInfiniteSharpness;
};

/// A control cage.
/// - `positions`: #V×3 doubles, object-space coordinates (the same units as TriangleMesh).
/// - `faceSizes`: #F entries, the corner count of each face (≥ 3; exactly 3 for Loop).
/// - `faceIndices`: Σ faceSizes vertex indices (< #V), face after face, each face
///   counter-clockwise seen from outside, like TriangleMesh triangles — the subdivided
///   surface keeps this orientation.
/// - `creases`, `corners`: sharpness tags, passed to OpenSubdiv in order; tag each edge
///   and vertex at most once (for repeats OpenSubdiv decides which value holds).
/// The surface is closed iff the cage is (every edge in exactly two faces).
struct SubdivisionCage {
    std::vector<glm::dvec3> positions;
    std::vector<std::uint32_t> faceSizes;
    std::vector<std::uint32_t> faceIndices;
    SubdivisionScheme scheme = SubdivisionScheme::CatmullClark;
    BoundaryInterpolation boundary = BoundaryInterpolation::EdgesAndCorners;
    std::vector<CageCrease> creases;
    std::vector<CageCorner> corners;

    [[nodiscard]] std::size_t vertexCount() const { return positions.size(); }
    [[nodiscard]] std::size_t faceCount() const { return faceSizes.size(); }
    /// First index of face `f` in faceIndices (O(f): sums the sizes before it).
    [[nodiscard]] std::size_t faceStart(std::size_t f) const;
    /// The vertices of face `f` (f < faceCount(), sizes consistent with faceIndices).
    [[nodiscard]] std::span<const std::uint32_t> face(std::size_t f) const;
};

/// The cage element a SubdivisionError is about (readers turn it into a file line).
struct CageElement {
    enum class Kind { Face, Crease, Corner };
    Kind kind = Kind::Face;
    std::size_t index = 0; ///< into faceSizes, creases or corners
};

/// What is wrong with a cage. `what()` is one sentence naming the element and saying what
/// to do, e.g. "cage face 3 repeats vertex 7; remove the repeated corner" (cage faces,
/// vertices, creases and corners count from 0). `element()` is the offending face, crease
/// or corner when the problem belongs to one.
class SubdivisionError : public std::runtime_error {
public:
    explicit SubdivisionError(const std::string& message, std::optional<CageElement> element = std::nullopt)
        : std::runtime_error(message), m_element(element)
    {
    }
    [[nodiscard]] std::optional<CageElement> element() const noexcept { return m_element; }

private:
    std::optional<CageElement> m_element;
};

/// Checks everything OpenSubdiv and the trim modes need and throws SubdivisionError for
/// the first problem found, in this order: no faces; faceSizes not summing to
/// faceIndices.size(); a face with < 3 corners; an index ≥ #V; a repeated vertex in a
/// face; a non-triangle under Loop ("Loop subdivision needs triangles ..."); a
/// non-finite position; an edge used by more than two faces (non-manifold) or twice in
/// the same direction (inconsistent orientation); a vertex used by no face; a crease whose
/// vertices are out of range or not joined by a cage edge; a corner out of range; a
/// negative or non-finite sharpness. Runs in O(Σ faceSizes · log).
void validateCage(const SubdivisionCage& cage);

} // namespace trimlab
