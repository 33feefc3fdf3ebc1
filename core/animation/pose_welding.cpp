#include "core/animation/pose_welding.h"

#include <bit>
#include <cstdint>
#include <unordered_map>

namespace trimlab {

namespace {

struct GroupKey {
    std::uint32_t group;
    std::uint32_t x;
    std::uint32_t y;
    std::uint32_t z;
    bool operator==(const GroupKey&) const = default;
};

struct GroupKeyHash {
    std::size_t operator()(const GroupKey& k) const
    {
        std::uint64_t h = 1469598103934665603ull;
        for (const std::uint32_t part : {k.group, k.x, k.y, k.z})
            h = (h ^ part) * 1099511628211ull;
        return std::size_t(h);
    }
};

std::uint32_t bits(float value)
{
    return std::bit_cast<std::uint32_t>(value == 0.0f ? 0.0f : value); // −0 joins +0
}

// Refines `group` (vertex → group id) by the positions of one pose: vertices stay
// together only if they were together and coincide in this pose too.
void refineByPose(const std::vector<glm::vec3>& positions, std::vector<std::uint32_t>& group)
{
    std::unordered_map<GroupKey, std::uint32_t, GroupKeyHash> ids;
    ids.reserve(positions.size());
    for (std::size_t v = 0; v < positions.size(); ++v) {
        const GroupKey key{group[v], bits(positions[v].x), bits(positions[v].y), bits(positions[v].z)};
        group[v] = ids.try_emplace(key, std::uint32_t(ids.size())).first->second;
    }
}

} // namespace

MeshAnimation weldAcrossPoses(const MeshAnimation& animation, std::vector<std::size_t>* kept)
{
    const std::size_t count = animation.vertexCount();
    std::vector<std::uint32_t> group(count, 0);
    for (const std::vector<glm::vec3>& pose : animation.poses)
        refineByPose(pose, group);
    // New index of every group in order of first appearance; the first vertex represents it.
    std::vector<std::uint32_t> newIndex(count, UINT32_MAX);
    std::vector<std::uint32_t> remap(count);
    std::vector<std::size_t> representatives;
    for (std::size_t v = 0; v < count; ++v) {
        if (newIndex[group[v]] == UINT32_MAX) {
            newIndex[group[v]] = std::uint32_t(representatives.size());
            representatives.push_back(v);
        }
        remap[v] = newIndex[group[v]];
    }
    MeshAnimation welded;
    welded.poseNames = animation.poseNames;
    welded.poseTimes = animation.poseTimes;
    welded.restPose = animation.restPose;
    for (const glm::uvec3& t : animation.triangles)
        welded.triangles.emplace_back(remap[t.x], remap[t.y], remap[t.z]);
    for (const std::vector<glm::vec3>& pose : animation.poses) {
        welded.poses.emplace_back();
        welded.poses.back().reserve(representatives.size());
        for (const std::size_t v : representatives)
            welded.poses.back().push_back(pose[v]);
    }
    if (kept)
        *kept = std::move(representatives);
    return welded;
}

} // namespace trimlab
