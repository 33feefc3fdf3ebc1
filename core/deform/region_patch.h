#pragma once
/// \file
/// The influenced region of a stroke plus the one-ring around it, renumbered 0..n−1 so
/// the per-drag work (warp, smoothing) runs on small dense arrays instead of #V-sized
/// ones. Built once per stroke.

#include "core/deform/brush_topology.h"

#include <cstdint>
#include <span>
#include <vector>

namespace trimlab::deform {

class RegionPatch {
public:
    /// One triangle around a region vertex r, seen from r: its other corners j and k (in
    /// the triangle's cyclic order after r) as local ids, and where j and k sit in r's
    /// local ring (indices into the ring arrays, ringOffset(r) + position).
    struct Wedge {
        std::uint32_t j = 0, k = 0;
        std::uint32_t slotJ = 0, slotK = 0;
    };

    /// An empty patch (no region).
    RegionPatch() = default;

    /// `region`: global vertex ids, sorted ascending, unique, in range
    /// (std::invalid_argument otherwise). Local ids [0, regionSize()) are the region
    /// vertices in that order; [regionSize(), size()) the halo: their neighbours outside
    /// the region, ascending.
    RegionPatch(const BrushTopology& topology, std::span<const std::uint32_t> region);

    [[nodiscard]] std::size_t regionSize() const { return m_regionSize; }
    [[nodiscard]] std::size_t size() const { return m_global.size(); }
    /// Global vertex id of local id i.
    [[nodiscard]] std::uint32_t global(std::size_t i) const { return m_global[i]; }

    /// Local ids of the one-ring of region vertex r, in ascending global order;
    /// slots ringOffset(r) .. ringOffset(r + 1) − 1.
    [[nodiscard]] std::uint32_t ringOffset(std::size_t r) const { return m_ringOffsets[r]; }
    [[nodiscard]] std::uint32_t ringNeighbour(std::uint32_t slot) const { return m_ring[slot]; }
    [[nodiscard]] std::size_t ringSlotCount() const { return m_ring.size(); }
    /// Non-degenerate incident triangles of region vertex r.
    [[nodiscard]] std::span<const Wedge> wedges(std::size_t r) const
    {
        return {m_wedges.data() + m_wedgeOffsets[r], m_wedges.data() + m_wedgeOffsets[r + 1]};
    }

private:
    std::size_t m_regionSize = 0;
    std::vector<std::uint32_t> m_global;
    std::vector<std::uint32_t> m_ringOffsets, m_ring;
    std::vector<std::uint32_t> m_wedgeOffsets;
    std::vector<Wedge> m_wedges;
};

} // namespace trimlab::deform
