#include "core/solid/trimmed_solid.h"

#include "core/solid/cell_windings.h"
#include "core/solid/exact_kernel.h"
#include "core/solid/refined_soup.h"
#include "core/trim/clip_polytope.h"
#include "core/trim/csg_expression.h"
#include "core/trim/static_rule.h"

#include <chrono>
#include <map>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

namespace trimlab {

namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// Whether the cell with windings `w` (one per object) belongs to the solid. With `cut`,
// the last object is the clip polytope: the cell must lie inside it too.
bool keptCell(const TrimSettings& settings, const std::vector<int>& w, bool cut)
{
    const std::size_t objects = cut ? w.size() - 1 : w.size();
    if (cut && w.back() <= 0)
        return false;
    if (!settings.csg.enabled())
        return isInterior(settings.rule, std::accumulate(w.begin(), w.begin() + std::ptrdiff_t(objects), 0));
    std::uint32_t inside = 0;
    for (std::size_t o = 0; o < objects && o < std::size_t(kMaxCsgOperands); ++o)
        if (isInterior(settings.objectRule(int(o)), w[o]))
            inside |= 1u << o;
    return evaluateCsg(settings.csg.expression, inside);
}

void countEdges(const TriangleMesh& mesh, TrimmedSolidStats& stats)
{
    std::unordered_map<std::uint64_t, int> faces;
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = t[k], b = t[(k + 1) % 3];
            ++faces[(std::uint64_t(std::min(a, b)) << 32) | std::max(a, b)];
        }
    for (const auto& [edge, count] : faces) {
        stats.nonManifoldEdges += count > 2 ? 1 : 0;
        stats.openEdges += count == 1 ? 1 : 0;
    }
}

// The float nearest an exact coordinate, the same whichever thread evaluated it first. A
// lazy number's interval narrows when some thread asks for its exact value, so rounding
// the interval's midpoint would give one float or its neighbour from run to run. When
// both ends of the interval round to one float the value does too (rounding is
// monotonic); otherwise the exact value decides.
float roundedCoordinate(const solid::ExactKernel::FT& x)
{
    const auto [low, high] = CGAL::to_interval(x);
    if (float(low) == float(high))
        return float(low);
    // The exact value lies between two neighbouring doubles: the lower one decides.
    return float(CGAL::to_interval(CGAL::exact(x)).first);
}

// The kept faces with float positions, as every file format stores them. Exact points
// closer than a float step round to one position: they become one vertex (a reader that
// welds by position would make them one anyway), and the faces that collapse with them
// (two corners on one vertex: slivers along intersection curves) are dropped.
TriangleMesh roundedMesh(const solid::RefinedSoup& soup, const std::vector<std::array<std::uint32_t, 3>>& kept,
                         TrimmedSolidStats& stats)
{
    TriangleMesh mesh;
    std::vector<std::int64_t> newIndex(soup.points.size(), -1);
    std::map<std::array<float, 3>, std::uint32_t> byPosition;
    std::size_t exactVertices = 0;
    long double volume = 0.0L;
    for (const std::array<std::uint32_t, 3>& v : kept) {
        glm::uvec3 triangle;
        for (int k = 0; k < 3; ++k) {
            std::int64_t& index = newIndex[v[std::size_t(k)]];
            if (index < 0) {
                ++exactVertices;
                const solid::ExactPoint& p = soup.points[v[std::size_t(k)]];
                const glm::vec3 rounded(roundedCoordinate(p.x()), roundedCoordinate(p.y()), roundedCoordinate(p.z()));
                const auto [it, inserted] = byPosition.emplace(std::array<float, 3>{rounded.x, rounded.y, rounded.z},
                                                               std::uint32_t(mesh.positions.size()));
                if (inserted)
                    mesh.positions.push_back(rounded);
                index = it->second;
            }
            triangle[k] = std::uint32_t(index);
        }
        if (triangle.x == triangle.y || triangle.y == triangle.z || triangle.z == triangle.x) {
            ++stats.roundingDroppedFaces;
            continue;
        }
        mesh.triangles.push_back(triangle);
        const glm::dvec3 a(mesh.positions[triangle.x]), b(mesh.positions[triangle.y]), c(mesh.positions[triangle.z]);
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    stats.roundingMergedVertices = exactVertices - mesh.positions.size();
    stats.signedVolume = double(volume);
    return mesh;
}

// trimmedSolid of `scene`, whose last object is the clip polytope when `cut`.
TrimmedSolid solidOf(const Scene& scene, const TrimSettings& settings, bool cut, const TaskControl& control)
{
    if (!settings.trimEnabled)
        throw std::invalid_argument("trimming is off: without a rule there is no solid to export");
    TrimmedSolid result;
    TrimmedSolidStats& stats = result.stats;
    auto start = std::chrono::steady_clock::now();
    const solid::RefinedSoup soup = solid::refineScene(scene, control);
    stats.refineMs = millisecondsSince(start);
    stats.inputTriangles = soup.inputTriangles;
    stats.degenerateTriangles = soup.degenerateTriangles;
    stats.refinedFaces = soup.faces.size();
    stats.cancelledFaces = soup.cancelledFaces;
    stats.profile = soup.profile;

    start = std::chrono::steady_clock::now();
    const solid::CellWindings cells = solid::cellWindings(soup, control);
    stats.boundaryPieces = cells.boundaryPieces;
    stats.components = cells.components;
    stats.contradictions = cells.contradictions;
    stats.profile.sortedEdges = cells.sortedEdges;
    stats.profile.rays = cells.components;
    stats.profile.wedgesMs = cells.wedgesMs;
    stats.profile.walkMs = cells.walkMs;
    stats.profile.raysMs = cells.raysMs;

    // The faces between a kept and a dropped cell, facing out of the kept one.
    std::vector<std::array<std::uint32_t, 3>> kept;
    for (std::size_t f = 0; f < soup.faces.size(); ++f) {
        const solid::RefinedFace& face = soup.faces[f];
        std::vector<int> behind = cells.front[f];
        for (std::size_t o = 0; o < behind.size(); ++o)
            behind[o] += face.delta[o];
        const bool keptInFront = keptCell(settings, cells.front[f], cut);
        if (keptInFront == keptCell(settings, behind, cut))
            continue;
        std::array<std::uint32_t, 3> v = face.vertices;
        if (keptInFront)
            std::swap(v[1], v[2]);
        kept.push_back(v);
    }
    stats.keptFaces = kept.size();
    result.mesh = roundedMesh(soup, kept, stats);
    stats.windingMs = millisecondsSince(start);
    countEdges(result.mesh, stats);
    return result;
}

} // namespace

TrimmedSolid trimmedSolid(const Scene& scene, const TrimSettings& settings, const TaskControl& control)
{
    return solidOf(scene, settings, false, control);
}

TrimmedSolid cutTrimmedSolid(const Scene& scene, const TrimSettings& settings, const TaskControl& control)
{
    const ClipSet clips = settings.clipSet();
    if (!clips.anyEnabled())
        return trimmedSolid(scene, settings, control);
    // A box around the scene, a tenth larger on every side, bounds the half-spaces: its
    // own faces then lie outside everything the rule keeps.
    Bounds box = scene.worldBounds();
    const glm::dvec3 margin = 0.1 * (box.max - box.min) + glm::dvec3(1e-3 * std::max(box.radius(), 1e-30));
    box.min -= margin;
    box.max += margin;
    Scene withRegion = scene;
    withRegion.objects.push_back({"clip region", clipPolytope(clips, box), glm::dmat4(1.0)});
    return solidOf(withRegion, settings, true, control);
}

} // namespace trimlab
