#pragma once
/// \file
/// Seeded region growing on the vertex graph (Adams & Bischof 1994), the step shared by
/// both pose partitioning methods: regions grow from seed vertices over mesh edges, each
/// time taking the unassigned boundary vertex whose feature is closest to the centre of
/// the region it borders. Regions are connected by construction.

#include "core/animation/vertex_graph.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

inline constexpr std::uint32_t kNoRegion = UINT32_MAX;

/// Per-vertex feature vectors: vertex v has values[v·dimension … (v+1)·dimension).
struct FeatureView {
    std::span<const double> values;
    std::size_t dimension = 1;

    /// Euclidean distance between the feature of vertex v and `center` (dimension values).
    [[nodiscard]] double distance(std::size_t v, std::span<const double> center) const;
};

/// The part of the graph regions may grow in: vertices with `labels[v] == id`, or every
/// vertex when `labels` is empty.
struct GrowthDomain {
    std::span<const std::uint32_t> labels;
    std::uint32_t id = 0;

    [[nodiscard]] bool contains(std::size_t v) const { return labels.empty() || labels[v] == id; }
};

/// Grows one region per seed (distinct vertices inside `domain`); `centers` holds
/// seeds.size() × dimension values. Returns #V region indices, kNoRegion for vertices
/// outside the domain or not reachable from any seed. The boundary vertex with the
/// smallest distance to its region's centre is taken first; ties go to the smaller
/// region index, then the smaller vertex index, so the result is deterministic.
/// O(E log E).
[[nodiscard]] std::vector<std::uint32_t> growRegions(const VertexGraph& graph, const FeatureView& feature,
                                                     std::span<const std::uint32_t> seeds,
                                                     std::span<const double> centers, const GrowthDomain& domain = {});

/// Lloyd-style refinement: grows regions from `seeds` with the seeds' own features as
/// centres, then repeatedly (at most `iterations` times, stopping when no seed moves)
/// sets each centre to its region's mean feature (weighted by `weights`, #V, e.g. vertex
/// areas), moves the seed to the region's vertex closest to that mean (ties: smaller
/// index) and grows again. Returns the last growth; `seeds` is updated.
[[nodiscard]] std::vector<std::uint32_t> refineRegions(const VertexGraph& graph, const FeatureView& feature,
                                                       std::span<const double> weights,
                                                       std::vector<std::uint32_t>& seeds, int iterations,
                                                       const GrowthDomain& domain = {});

} // namespace trimlab
