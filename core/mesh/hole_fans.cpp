#include "core/mesh/hole_fans.h"

#include "core/mesh/boundary_loops.h"

#include <stdexcept>
#include <string>

namespace trimlab {

HoleFans holeFans(std::span<const glm::uvec3> triangles, std::size_t vertexCount)
{
    HoleFans fans;
    fans.loops = boundaryLoops(triangles);
    fans.firstCentre = std::uint32_t(vertexCount);
    for (std::size_t l = 0; l < fans.loops.size(); ++l) {
        const std::vector<std::uint32_t>& loop = fans.loops[l];
        const std::uint32_t centre = fans.firstCentre + std::uint32_t(l);
        for (std::size_t i = 0; i < loop.size(); ++i)
            fans.triangles.emplace_back(loop[i], loop[(i + 1) % loop.size()], centre);
    }
    return fans;
}

std::vector<glm::vec3> withHoleCentres(const HoleFans& fans, const std::vector<glm::vec3>& positions)
{
    if (positions.size() != fans.firstCentre)
        throw std::invalid_argument("the fans close a mesh of " + std::to_string(fans.firstCentre) + " vertices, not " +
                                    std::to_string(positions.size()));
    std::vector<glm::vec3> closed = positions;
    for (const std::vector<std::uint32_t>& loop : fans.loops) {
        glm::dvec3 sum(0.0);
        for (std::uint32_t v : loop)
            sum += glm::dvec3(positions[v]);
        closed.push_back(glm::vec3(sum / double(loop.size())));
    }
    return closed;
}

TriangleMesh closeHoles(const TriangleMesh& mesh)
{
    const HoleFans fans = holeFans(mesh.triangles, mesh.positions.size());
    if (fans.empty())
        return mesh;
    TriangleMesh closed;
    closed.positions = withHoleCentres(fans, mesh.positions);
    closed.triangles = mesh.triangles;
    closed.triangles.insert(closed.triangles.end(), fans.triangles.begin(), fans.triangles.end());
    return closed;
}

} // namespace trimlab
