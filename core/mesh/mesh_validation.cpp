#include "core/mesh/mesh_validation.h"

#include "core/util/union_find.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace trimlab {

namespace {

// One side of a triangle, from corner `corner` to the next corner, keyed by its
// undirected edge so that sorting groups all sides along the same edge.
struct TriangleSide {
    std::uint64_t key; // (min vertex << 32) | max vertex
    std::size_t face;
    std::uint8_t corner;
    bool forward; // runs from the smaller to the larger vertex index

    [[nodiscard]] std::uint32_t low() const { return static_cast<std::uint32_t>(key >> 32); }
    [[nodiscard]] std::uint32_t high() const { return static_cast<std::uint32_t>(key & 0xFFFFFFFFu); }
    // The corner of this side's face that sits at the edge's smaller / larger vertex.
    [[nodiscard]] std::size_t cornerAtLow() const { return 3 * face + (forward ? corner : (corner + 1) % 3); }
    [[nodiscard]] std::size_t cornerAtHigh() const { return 3 * face + (forward ? (corner + 1) % 3 : corner); }
};

bool isFinite(const glm::vec3& p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// Marks faces with an out-of-range index invalid; records degenerate faces.
std::vector<char> checkFaces(const TriangleMesh& mesh, MeshValidationReport& report)
{
    std::vector<char> valid(mesh.triangles.size(), 1);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        const glm::uvec3 t = mesh.triangles[f];
        if (t[0] >= mesh.positions.size() || t[1] >= mesh.positions.size() || t[2] >= mesh.positions.size()) {
            valid[f] = 0;
            report.outOfRangeFaces.add(f);
            continue;
        }
        const glm::vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
        bool degenerate = t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
        if (!degenerate && isFinite(a) && isFinite(b) && isFinite(c)) {
            const glm::dvec3 n = glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a));
            degenerate = n.x == 0.0 && n.y == 0.0 && n.z == 0.0;
        }
        if (degenerate)
            report.degenerateFaces.add(f);
    }
    return valid;
}

std::vector<TriangleSide> collectSides(const TriangleMesh& mesh, const std::vector<char>& valid)
{
    std::vector<TriangleSide> sides;
    sides.reserve(3 * mesh.triangles.size());
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        if (!valid[f])
            continue;
        for (std::uint8_t k = 0; k < 3; ++k) {
            const std::uint32_t from = mesh.triangles[f][k];
            const std::uint32_t to = mesh.triangles[f][(k + 1) % 3];
            if (from == to)
                continue; // the collapsed side of a degenerate face bounds nothing
            const std::uint64_t lo = std::min(from, to);
            const std::uint64_t hi = std::max(from, to);
            sides.push_back({(lo << 32) | hi, f, k, from < to});
        }
    }
    std::sort(sides.begin(), sides.end(), [](const TriangleSide& x, const TriangleSide& y) {
        return x.key != y.key ? x.key < y.key : x.face < y.face;
    });
    return sides;
}

// Classifies every undirected edge; joins the corners of the two faces of each
// two-face edge so that corners in one fan end up in one set.
void analyseEdges(const std::vector<TriangleSide>& sides, MeshValidationReport& report, UnionFind& corners)
{
    for (std::size_t begin = 0; begin < sides.size();) {
        std::size_t end = begin;
        MeshEdge edge{sides[begin].low(), sides[begin].high(), 0, 0};
        for (; end < sides.size() && sides[end].key == sides[begin].key; ++end)
            ++(sides[end].forward ? edge.forward : edge.backward);
        ++report.edgeCount;
        if (edge.uses() == 1)
            report.boundaryEdges.add(edge);
        if (edge.uses() > 2)
            report.nonManifoldEdges.add(edge);
        if (edge.uses() == 2 && edge.forward != edge.backward)
            report.inconsistentEdges.add(edge);
        if (edge.forward != edge.backward)
            report.unbalancedEdges.add(edge);
        if (edge.uses() == 2) {
            corners.unite(sides[begin].cornerAtLow(), sides[begin + 1].cornerAtLow());
            corners.unite(sides[begin].cornerAtHigh(), sides[begin + 1].cornerAtHigh());
        }
        begin = end;
    }
}

void findNonManifoldVertices(const TriangleMesh& mesh, const std::vector<char>& valid, UnionFind& corners,
                             MeshValidationReport& report)
{
    constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
    std::vector<std::size_t> fanOf(mesh.positions.size(), none);
    std::vector<char> several(mesh.positions.size(), 0);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        if (!valid[f])
            continue;
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t v = mesh.triangles[f][static_cast<glm::length_t>(k)];
            const std::size_t fan = corners.find(3 * f + k);
            if (fanOf[v] == none)
                fanOf[v] = fan;
            else if (fanOf[v] != fan)
                several[v] = 1;
        }
    }
    for (std::uint32_t v = 0; v < several.size(); ++v) {
        if (several[v])
            report.nonManifoldVertices.add(v);
    }
}

// Components, unreferenced vertices and the referenced-vertex count (for χ).
std::size_t analyseConnectivity(const TriangleMesh& mesh, const std::vector<char>& valid, MeshValidationReport& report)
{
    UnionFind vertices(mesh.positions.size());
    std::vector<char> referenced(mesh.positions.size(), 0);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        if (!valid[f])
            continue;
        const glm::uvec3 t = mesh.triangles[f];
        vertices.unite(t[0], t[1]);
        vertices.unite(t[1], t[2]);
        referenced[t[0]] = referenced[t[1]] = referenced[t[2]] = 1;
    }
    std::size_t referencedCount = 0;
    for (std::uint32_t v = 0; v < referenced.size(); ++v) {
        if (!referenced[v]) {
            report.unreferencedVertices.add(v);
            continue;
        }
        ++referencedCount;
        if (vertices.find(v) == v)
            ++report.componentCount;
    }
    return referencedCount;
}

double signedVolume(const TriangleMesh& mesh, const std::vector<char>& valid, const glm::dvec3& origin)
{
    double sixTimesVolume = 0.0;
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        if (!valid[f])
            continue;
        const glm::uvec3 t = mesh.triangles[f];
        const glm::dvec3 a = glm::dvec3(mesh.positions[t[0]]) - origin;
        const glm::dvec3 b = glm::dvec3(mesh.positions[t[1]]) - origin;
        const glm::dvec3 c = glm::dvec3(mesh.positions[t[2]]) - origin;
        const double term = glm::dot(a, glm::cross(b, c));
        if (std::isfinite(term))
            sixTimesVolume += term;
    }
    return sixTimesVolume / 6.0;
}

void computeTopology(MeshValidationReport& report, std::size_t referencedVertices, std::size_t validFaces)
{
    if (!report.closed() || !report.manifold())
        return;
    const auto chi = static_cast<std::int64_t>(referencedVertices) - static_cast<std::int64_t>(report.edgeCount) +
                     static_cast<std::int64_t>(validFaces);
    report.eulerCharacteristic = chi;
    const std::int64_t twiceGenus = 2 * static_cast<std::int64_t>(report.componentCount) - chi;
    if (!report.inconsistentEdges.any() && twiceGenus >= 0 && twiceGenus % 2 == 0)
        report.genus = twiceGenus / 2;
}

} // namespace

bool MeshValidationReport::closed() const
{
    return triangleCount > 0 && !boundaryEdges.any() && !outOfRangeFaces.any();
}

bool MeshValidationReport::manifold() const
{
    return !nonManifoldEdges.any() && !nonManifoldVertices.any();
}

bool MeshValidationReport::trimmable() const
{
    return triangleCount > 0 && !unbalancedEdges.any() && !nonFiniteVertices.any() && !outOfRangeFaces.any();
}

MeshValidationReport validateMesh(const TriangleMesh& mesh)
{
    MeshValidationReport report;
    report.vertexCount = mesh.positions.size();
    report.triangleCount = mesh.triangles.size();
    report.bounds = computeBounds(mesh);
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
        if (!isFinite(mesh.positions[v]))
            report.nonFiniteVertices.add(v);
    }
    const std::vector<char> valid = checkFaces(mesh, report);
    const std::size_t validFaces = mesh.triangles.size() - report.outOfRangeFaces.count;
    UnionFind corners(3 * mesh.triangles.size());
    analyseEdges(collectSides(mesh, valid), report, corners);
    findNonManifoldVertices(mesh, valid, corners, report);
    const std::size_t referenced = analyseConnectivity(mesh, valid, report);
    computeTopology(report, referenced, validFaces);
    report.signedVolume = signedVolume(mesh, valid, report.bounds.valid() ? report.bounds.center() : glm::dvec3(0.0));
    return report;
}

std::string unusableGeometryReason(const TriangleMesh& mesh)
{
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::vec3& p = mesh.positions[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return "vertex " + std::to_string(v) + " is not finite";
    }
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::dvec3 a(mesh.positions[t.x]);
        const glm::dvec3 b(mesh.positions[t.y]);
        const glm::dvec3 c(mesh.positions[t.z]);
        if (glm::length(glm::cross(b - a, c - a)) > 0.0)
            return {};
    }
    return "the geometry is degenerate: all " + std::to_string(mesh.triangles.size()) +
           " triangles have zero area (the vertices lie on one line or point)";
}

} // namespace trimlab
