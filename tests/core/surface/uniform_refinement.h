#pragma once
/// \file
/// A subdivision cage refined uniformly by OpenSubdiv's own Far::PrimvarRefiner, level by
/// level: an evaluation path independent of the stencil tables of SubdivisionSurface,
/// used as the reference of tst_subdivision_surface and as the "from scratch" cost in
/// bench_subdivision.

#include "core/surface/subdivision_cages.h"

#include <opensubdiv/far/topologyRefiner.h>

#include <glm/vec3.hpp>

#include <memory>
#include <vector>

namespace trimlab::test {

/// A position in OpenSubdiv's primvar protocol (Clear, AddWithWeight), which its
/// refiners, limit masks and stencil tables blend.
struct OsdPoint {
    glm::dvec3 p{0.0};
    void Clear(void* = nullptr) { p = glm::dvec3(0.0); }
    void AddWithWeight(const OsdPoint& source, double weight) { p += weight * source.p; }
};

struct UniformRefinement {
    std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> refiner; ///< refined to the requested level
    std::vector<OsdPoint> points; ///< the last level's vertices, in OpenSubdiv's vertex order
};

/// Refines `cage` uniformly `level` times (0: the cage itself) and interpolates its
/// positions through every level. `fullTopologyInLastLevel` keeps the last level's full
/// topology, which limitOfRefined() needs. Throws SubdivisionError when OpenSubdiv refuses
/// the cage (createCageRefiner).
[[nodiscard]] UniformRefinement refineUniformly(const SubdivisionCage& cage, int level, bool fullTopologyInLastLevel);

/// Limit positions and the two first derivatives (OpenSubdiv's tangents, not normalised)
/// of a refinement's last-level vertices, by OpenSubdiv's limit masks
/// (PrimvarRefiner::Limit); #points each.
struct LimitPoints {
    std::vector<OsdPoint> position;
    std::vector<OsdPoint> du;
    std::vector<OsdPoint> dv;
};

/// `refinement` must come from refineUniformly with fullTopologyInLastLevel = true.
[[nodiscard]] LimitPoints limitOfRefined(const UniformRefinement& refinement);

} // namespace trimlab::test
