#include "core/trim/hole_closing.h"

#include "core/trim/ray_triangle.h"

#include <glm/geometric.hpp>

namespace trimlab {

namespace {

bool meets(const Bounds& a, const Bounds& b)
{
    return glm::all(glm::lessThanEqual(a.min, b.max)) && glm::all(glm::lessThanEqual(b.min, a.max));
}

glm::dvec3 at(std::span<const glm::vec3> positions, std::uint32_t v)
{
    return glm::dvec3(positions[v]);
}

Bounds triangleBox(const glm::uvec3& t, std::span<const glm::vec3> positions)
{
    Bounds box;
    for (int i = 0; i < 3; ++i)
        box.extend(at(positions, t[i]));
    return box;
}

bool hasVertex(const glm::uvec3& t, std::uint32_t v)
{
    return t.x == v || t.y == v || t.z == v;
}

// Whether the segment from vertex `from` to vertex `to` passes through triangle `t` at a
// point other than its start (the end is a vertex of the other surface, so a hit exactly
// there counts: the segment reaches the triangle).
bool segmentCrosses(std::span<const glm::vec3> positions, std::uint32_t from, std::uint32_t to, const glm::uvec3& t)
{
    if (hasVertex(t, from))
        return false;
    const glm::dvec3 a = at(positions, from);
    const glm::dvec3 b = at(positions, to);
    if (a == b)
        return false;
    const WatertightRay ray = makeWatertightRay(PixelRay{a, b - a});
    const std::optional<TriangleHit> hit =
        intersectTriangle(ray, at(positions, t.x), at(positions, t.y), at(positions, t.z));
    return hit && hit->t > 0.0 && hit->t <= 1.0;
}

// Whether fan triangle `fan` (corners: loop corner, next corner, centre) and mesh
// triangle `mesh` cross: a spoke of the fan through the mesh triangle, or an edge of the
// mesh triangle through the fan (both directions, so a crossing is found whichever
// triangle's edge pierces the other). The fan's rim edge lies on the mesh: not tested.
bool trianglesCross(std::span<const glm::vec3> positions, const glm::uvec3& fan, const glm::uvec3& mesh)
{
    const std::uint32_t centre = fan.z;
    if (segmentCrosses(positions, fan.x, centre, mesh) || segmentCrosses(positions, fan.y, centre, mesh))
        return true;
    for (int i = 0; i < 3; ++i) {
        const std::uint32_t from = mesh[i];
        const std::uint32_t to = mesh[(i + 1) % 3];
        if (hasVertex(fan, from) || hasVertex(fan, to))
            continue; // an edge of the rim, or one that meets the fan at a loop corner
        if (segmentCrosses(positions, from, to, fan) || segmentCrosses(positions, to, from, fan))
            return true;
    }
    return false;
}

} // namespace

HoleClosing& HoleClosing::operator+=(const HoleClosing& other)
{
    holes += other.holes;
    edges += other.edges;
    if (crossing.empty())
        crossing = other.crossing;
    crossingMeshes += other.crossingMeshes;
    return *this;
}

std::string holeClosingText(const HoleClosing& closing)
{
    if (closing.holes == 0)
        return "no holes";
    std::string text = std::to_string(closing.holes) + (closing.holes == 1 ? " hole of " : " holes of ") +
                       std::to_string(closing.edges) + (closing.edges == 1 ? " edge" : " edges");
    if (!closing.crossing.empty())
        text += "; warning: " + closing.crossing;
    if (closing.crossingMeshes > 1)
        text += " (fans cross in " + std::to_string(closing.crossingMeshes) + " poses or objects)";
    return text;
}

std::optional<FanCrossing> firstFanCrossing(const HoleFans& fans, std::span<const glm::uvec3> triangles,
                                            std::span<const glm::vec3> positions)
{
    std::size_t first = 0; // the loop's first fan triangle in fans.triangles
    for (std::size_t l = 0; l < fans.loops.size(); ++l) {
        const std::span<const glm::uvec3> fan(fans.triangles.data() + first, fans.loops[l].size());
        first += fans.loops[l].size();
        Bounds fanBox;
        for (const glm::uvec3& t : fan)
            for (int i = 0; i < 3; ++i)
                fanBox.extend(at(positions, t[i]));
        for (std::size_t m = 0; m < triangles.size(); ++m) {
            if (!meets(triangleBox(triangles[m], positions), fanBox))
                continue;
            for (const glm::uvec3& t : fan)
                if (trianglesCross(positions, t, triangles[m]))
                    return FanCrossing{l, m};
        }
    }
    return std::nullopt;
}

TriangleMesh closedMesh(const TriangleMesh& mesh, HoleClosing* closing, const std::string& where)
{
    const HoleFans fans = holeFans(mesh.triangles, mesh.positions.size());
    if (closing)
        *closing = HoleClosing{fans.loops.size(), fans.triangles.size(), {}, 0};
    if (fans.empty())
        return mesh;
    TriangleMesh closed;
    closed.positions = withHoleCentres(fans, mesh.positions);
    if (const std::optional<FanCrossing> crossing = firstFanCrossing(fans, mesh.triangles, closed.positions);
        crossing && closing) {
        closing->crossing = where + fanCrossingMessage(fans, *crossing);
        closing->crossingMeshes = 1;
    }
    closed.triangles = mesh.triangles;
    closed.triangles.insert(closed.triangles.end(), fans.triangles.begin(), fans.triangles.end());
    return closed;
}

std::string fanCrossingMessage(const HoleFans& fans, const FanCrossing& crossing)
{
    const std::vector<std::uint32_t>& loop = fans.loops[crossing.loop];
    return "the fan closing the hole of " + std::to_string(loop.size()) + " edges at vertex " +
           std::to_string(loop.front()) + " crosses triangle " + std::to_string(crossing.meshTriangle) +
           ", so the trim may be wrong between them (fill that hole in a mesh editor to be sure)";
}

} // namespace trimlab
