#include "core/deform/region_patch.h"

#include "core/deform/local_vertex_map.h"

#include <algorithm>
#include <stdexcept>

namespace trimlab::deform {

namespace {

using LocalIds = LocalVertexMap<std::uint32_t>;

// Region ids first, then the halo (ring neighbours outside the region), both ascending.
std::vector<std::uint32_t> patchVertices(const BrushTopology& topology, std::span<const std::uint32_t> region)
{
    for (std::size_t i = 0; i < region.size(); ++i) {
        if (region[i] >= topology.vertexCount() || (i > 0 && region[i] <= region[i - 1]))
            throw std::invalid_argument("RegionPatch: region must be sorted, unique and in range");
    }
    LocalVertexMap<std::uint8_t> inRegion(region.size());
    for (std::uint32_t v : region)
        inRegion[v] = 1;
    std::vector<std::uint32_t> halo;
    for (std::uint32_t v : region) {
        for (const std::uint32_t* u = topology.ringBegin(v); u != topology.ringEnd(v); ++u) {
            if (inRegion.find(*u) == nullptr)
                halo.push_back(*u);
        }
    }
    std::sort(halo.begin(), halo.end());
    halo.erase(std::unique(halo.begin(), halo.end()), halo.end());
    std::vector<std::uint32_t> all(region.begin(), region.end());
    all.insert(all.end(), halo.begin(), halo.end());
    return all;
}

} // namespace

RegionPatch::RegionPatch(const BrushTopology& topology, std::span<const std::uint32_t> region)
    : m_regionSize(region.size()), m_global(patchVertices(topology, region))
{
    LocalIds local(m_global.size());
    for (std::uint32_t i = 0; i < m_global.size(); ++i)
        local[m_global[i]] = i;

    m_ringOffsets.push_back(0);
    m_wedgeOffsets.push_back(0);
    for (std::size_t r = 0; r < m_regionSize; ++r) {
        const std::uint32_t v = m_global[r];
        const std::uint32_t* ring = topology.ringBegin(v);
        const std::uint32_t* ringEnd = topology.ringEnd(v);
        for (const std::uint32_t* u = ring; u != ringEnd; ++u)
            m_ring.push_back(*local.find(*u));
        // The topology ring is sorted, so a neighbour's slot is its rank in it.
        auto slotOf = [&](std::uint32_t u) {
            return m_ringOffsets[r] + static_cast<std::uint32_t>(std::lower_bound(ring, ringEnd, u) - ring);
        };
        for (const std::uint32_t* f = topology.facesBegin(v); f != topology.facesEnd(v); ++f) {
            const glm::uvec3& t = topology.triangles()[*f];
            const int corner = t.x == v ? 0 : (t.y == v ? 1 : 2);
            const std::uint32_t j = t[(corner + 1) % 3], k = t[(corner + 2) % 3];
            if (j == v || k == v || j == k)
                continue;
            m_wedges.push_back({*local.find(j), *local.find(k), slotOf(j), slotOf(k)});
        }
        m_ringOffsets.push_back(static_cast<std::uint32_t>(m_ring.size()));
        m_wedgeOffsets.push_back(static_cast<std::uint32_t>(m_wedges.size()));
    }
}

} // namespace trimlab::deform
