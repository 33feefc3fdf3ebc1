#include "core/animation/pose_topology.h"

#include "core/mesh/mesh_load_error.h"

#include <algorithm>
#include <cstdint>

namespace trimlab {

namespace {

std::string triangleText(const glm::uvec3& t)
{
    return "(" + std::to_string(t.x) + ", " + std::to_string(t.y) + ", " + std::to_string(t.z) + ")";
}

// The directed edges of `faces` that are not cancelled by an edge in the opposite
// direction, sorted: the oriented boundary of the region the faces cover.
std::vector<std::uint64_t> regionBoundary(const std::vector<glm::uvec3>& faces)
{
    // Undirected key (low << 32 | high) with the direction in a separate flag.
    std::vector<std::pair<std::uint64_t, bool>> edges;
    edges.reserve(3 * faces.size());
    for (const glm::uvec3& t : faces) {
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t a = t[c];
            const std::uint32_t b = t[(c + 1) % 3];
            edges.emplace_back((std::uint64_t(std::min(a, b)) << 32) | std::max(a, b), a < b);
        }
    }
    std::sort(edges.begin(), edges.end());
    std::vector<std::uint64_t> boundary;
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        long net = 0; // uses low → high minus uses high → low
        for (; j < edges.size() && edges[j].first == edges[i].first; ++j)
            net += edges[j].second ? 1 : -1;
        const std::uint64_t key = edges[i].first;
        const std::uint64_t reversed = (key << 32) | (key >> 32);
        for (long k = 0; k < (net < 0 ? -net : net); ++k)
            boundary.push_back(net > 0 ? key : reversed);
        i = j;
    }
    std::sort(boundary.begin(), boundary.end());
    return boundary;
}

std::vector<std::uint32_t> cornerSet(const std::vector<glm::uvec3>& faces)
{
    std::vector<std::uint32_t> corners;
    for (const glm::uvec3& t : faces)
        corners.insert(corners.end(), {t.x, t.y, t.z});
    std::sort(corners.begin(), corners.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    return corners;
}

// True when the triangles that differ are a re-triangulation of the same polygons.
bool isRetriangulation(const std::vector<glm::uvec3>& first, const std::vector<glm::uvec3>& other)
{
    std::vector<glm::uvec3> a;
    std::vector<glm::uvec3> b;
    for (std::size_t f = 0; f < first.size(); ++f) {
        if (first[f] != other[f]) {
            a.push_back(first[f]);
            b.push_back(other[f]);
        }
    }
    return cornerSet(a) == cornerSet(b) && regionBoundary(a) == regionBoundary(b);
}

} // namespace

void requireSameTopology(const std::vector<glm::uvec3>& triangles, std::size_t vertexCount, const TriangleMesh& pose,
                         const std::string& poseName)
{
    if (pose.positions.size() != vertexCount)
        throw MeshLoadError(poseName, "has " + std::to_string(pose.positions.size()) +
                                          " vertices but the first pose has " + std::to_string(vertexCount));
    if (pose.triangles.size() != triangles.size())
        throw MeshLoadError(poseName, "has " + std::to_string(pose.triangles.size()) +
                                          " triangles but the first pose has " + std::to_string(triangles.size()));
    const auto mismatch = std::mismatch(triangles.begin(), triangles.end(), pose.triangles.begin());
    if (mismatch.first == triangles.end() || isRetriangulation(triangles, pose.triangles))
        return;
    const auto face = static_cast<std::size_t>(mismatch.first - triangles.begin());
    throw MeshLoadError(poseName, "face " + std::to_string(face) + " is " + triangleText(*mismatch.second) +
                                      " but the first pose has " + triangleText(*mismatch.first));
}

} // namespace trimlab
