#include "core/mesh/vertex_welding.h"

#include <bit>
#include <cstdint>
#include <unordered_map>

namespace trimlab {

namespace {

struct PositionBits {
    std::uint32_t x, y, z;
    bool operator==(const PositionBits&) const = default;
};

struct PositionBitsHash {
    std::size_t operator()(const PositionBits& p) const
    {
        std::uint64_t h = p.x;
        h = h * 0x9E3779B97F4A7C15ull ^ p.y;
        h = h * 0x9E3779B97F4A7C15ull ^ p.z;
        return static_cast<std::size_t>(h ^ (h >> 29));
    }
};

PositionBits bitsOf(const glm::vec3& p)
{
    // Adding +0 turns −0 into +0 and leaves every other value unchanged.
    return {std::bit_cast<std::uint32_t>(p.x + 0.0f), std::bit_cast<std::uint32_t>(p.y + 0.0f),
            std::bit_cast<std::uint32_t>(p.z + 0.0f)};
}

} // namespace

TriangleMesh weldIdenticalVertices(const TriangleMesh& mesh)
{
    TriangleMesh welded;
    std::unordered_map<PositionBits, std::uint32_t, PositionBitsHash> firstWithPosition;
    firstWithPosition.reserve(mesh.positions.size());
    std::vector<std::uint32_t> remap(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const auto next = static_cast<std::uint32_t>(welded.positions.size());
        const auto [it, inserted] = firstWithPosition.try_emplace(bitsOf(mesh.positions[v]), next);
        if (inserted)
            welded.positions.push_back(mesh.positions[v]);
        remap[v] = it->second;
    }
    welded.triangles.reserve(mesh.triangles.size());
    for (const glm::uvec3& t : mesh.triangles)
        welded.triangles.emplace_back(remap[t[0]], remap[t[1]], remap[t[2]]);
    return welded;
}

} // namespace trimlab
