#include "core/surface/subdivision_cage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>
#include <utility>

namespace trimlab {

std::size_t SubdivisionCage::faceStart(std::size_t f) const
{
    return std::accumulate(faceSizes.begin(), faceSizes.begin() + std::ptrdiff_t(f), std::size_t(0));
}

std::span<const std::uint32_t> SubdivisionCage::face(std::size_t f) const
{
    return std::span<const std::uint32_t>(faceIndices).subspan(faceStart(f), faceSizes[f]);
}

namespace {

std::string str(std::size_t value)
{
    return std::to_string(value);
}

CageElement faceElement(std::size_t f)
{
    return {CageElement::Kind::Face, f};
}

std::string sharpnessText(double sharpness)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g", sharpness);
    return text;
}

void requireFaces(const SubdivisionCage& cage)
{
    if (cage.faceCount() == 0)
        throw SubdivisionError("the cage has no faces; a subdivision surface needs at least one polygon");
    std::size_t total = 0;
    for (const std::uint32_t size : cage.faceSizes)
        total += size;
    if (total != cage.faceIndices.size())
        throw SubdivisionError("the cage's face sizes add up to " + str(total) + " corners, but it lists " +
                               str(cage.faceIndices.size()) + " face indices");
    std::size_t start = 0;
    for (std::size_t f = 0; f < cage.faceCount(); ++f) {
        const std::span<const std::uint32_t> face(cage.faceIndices.data() + start, cage.faceSizes[f]);
        start += cage.faceSizes[f];
        if (face.size() < 3)
            throw SubdivisionError("cage face " + str(f) + " has " + str(face.size()) +
                                       " corners; a face needs at least 3",
                                   faceElement(f));
        for (std::size_t i = 0; i < face.size(); ++i) {
            if (face[i] >= cage.vertexCount())
                throw SubdivisionError("cage face " + str(f) + " references vertex " + str(face[i]) +
                                           ", but the cage has only " + str(cage.vertexCount()) + " vertices",
                                       faceElement(f));
            if (std::find(face.begin(), face.begin() + std::ptrdiff_t(i), face[i]) != face.begin() + std::ptrdiff_t(i))
                throw SubdivisionError("cage face " + str(f) + " repeats vertex " + str(face[i]) +
                                           "; remove the repeated corner",
                                       faceElement(f));
        }
        if (cage.scheme == SubdivisionScheme::Loop && face.size() != 3)
            throw SubdivisionError("Loop subdivision needs triangles, but cage face " + str(f) + " has " +
                                       str(face.size()) + " corners; triangulate the cage or use Catmull-Clark",
                                   faceElement(f));
    }
}

void requireFinitePositions(const SubdivisionCage& cage)
{
    for (std::size_t v = 0; v < cage.vertexCount(); ++v) {
        const glm::dvec3& p = cage.positions[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw SubdivisionError("cage vertex " + str(v) +
                                   " has a non-finite coordinate; coordinates must be finite numbers");
    }
}

// A directed cage edge (from, to) and the face it belongs to.
struct DirectedEdge {
    std::uint32_t lo, hi;
    bool forward; // from == lo
    std::size_t face;
};

std::vector<DirectedEdge> directedEdges(const SubdivisionCage& cage)
{
    std::vector<DirectedEdge> edges;
    edges.reserve(cage.faceIndices.size());
    std::size_t start = 0;
    for (std::size_t f = 0; f < cage.faceCount(); ++f) {
        const std::size_t n = cage.faceSizes[f];
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint32_t a = cage.faceIndices[start + i];
            const std::uint32_t b = cage.faceIndices[start + (i + 1) % n];
            edges.push_back({std::min(a, b), std::max(a, b), a < b, f});
        }
        start += n;
    }
    std::stable_sort(edges.begin(), edges.end(), [](const DirectedEdge& x, const DirectedEdge& y) {
        return std::pair(x.lo, x.hi) < std::pair(y.lo, y.hi);
    });
    return edges;
}

void requireManifoldEdges(const std::vector<DirectedEdge>& edges)
{
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i + 1;
        while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi)
            ++j;
        const std::string name = "cage edge " + str(edges[i].lo) + "-" + str(edges[i].hi);
        if (j - i > 2)
            throw SubdivisionError(name + " is used by " + str(j - i) + " faces (non-manifold; first faces " +
                                       str(edges[i].face) + ", " + str(edges[i + 1].face) + ", " +
                                       str(edges[i + 2].face) + "); each edge may border at most two faces",
                                   faceElement(edges[i + 2].face));
        if (j - i == 2 && edges[i].forward == edges[i + 1].forward)
            throw SubdivisionError(name + " runs the same way in faces " + str(edges[i].face) + " and " +
                                       str(edges[i + 1].face) +
                                       " (inconsistent orientation); reverse one of them so neighbours agree",
                                   faceElement(edges[i + 1].face));
        i = j;
    }
}

void requireUsedVertices(const SubdivisionCage& cage)
{
    std::vector<bool> used(cage.vertexCount(), false);
    for (const std::uint32_t v : cage.faceIndices)
        used[v] = true;
    for (std::size_t v = 0; v < used.size(); ++v) {
        if (!used[v])
            throw SubdivisionError("cage vertex " + str(v) + " is used by no face; remove unused vertices");
    }
}

void requireSharpness(float sharpness, const std::string& what, CageElement element)
{
    if (!std::isfinite(sharpness) || sharpness < 0.0f)
        throw SubdivisionError(what + " has sharpness " + sharpnessText(sharpness) +
                                   "; use a finite value >= 0 (10 or more is infinitely sharp)",
                               element);
}

void requireTags(const SubdivisionCage& cage, const std::vector<DirectedEdge>& edges)
{
    for (std::size_t c = 0; c < cage.creases.size(); ++c) {
        const CageCrease& crease = cage.creases[c];
        const std::string name = "crease " + str(c) + " (" + str(crease.a) + "-" + str(crease.b) + ")";
        const CageElement element{CageElement::Kind::Crease, c};
        if (crease.a >= cage.vertexCount() || crease.b >= cage.vertexCount())
            throw SubdivisionError(name + " names a vertex >= " + str(cage.vertexCount()) + ", the cage's vertex count",
                                   element);
        const std::uint32_t lo = std::min(crease.a, crease.b), hi = std::max(crease.a, crease.b);
        const auto it = std::lower_bound(edges.begin(), edges.end(), std::pair(lo, hi),
                                         [](const DirectedEdge& e, const std::pair<std::uint32_t, std::uint32_t>& key) {
                                             return std::pair(e.lo, e.hi) < key;
                                         });
        if (it == edges.end() || it->lo != lo || it->hi != hi)
            throw SubdivisionError(name + " is not an edge of the cage; a crease must join two corners that follow "
                                          "each other in a face",
                                   element);
        requireSharpness(crease.sharpness, name, element);
    }
    for (std::size_t c = 0; c < cage.corners.size(); ++c) {
        const CageCorner& corner = cage.corners[c];
        const std::string name = "corner " + str(c) + " (vertex " + str(corner.vertex) + ")";
        const CageElement element{CageElement::Kind::Corner, c};
        if (corner.vertex >= cage.vertexCount())
            throw SubdivisionError(name + " names a vertex >= " + str(cage.vertexCount()) + ", the cage's vertex count",
                                   element);
        requireSharpness(corner.sharpness, name, element);
    }
}

} // namespace

void validateCage(const SubdivisionCage& cage)
{
    requireFaces(cage);
    requireFinitePositions(cage);
    const std::vector<DirectedEdge> edges = directedEdges(cage);
    requireManifoldEdges(edges);
    requireUsedVertices(cage);
    requireTags(cage, edges);
}

} // namespace trimlab
