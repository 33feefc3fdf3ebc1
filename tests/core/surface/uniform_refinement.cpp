#include "uniform_refinement.h"

#include "core/surface/cage_refiner.h"

#include <opensubdiv/far/primvarRefiner.h>

namespace trimlab::test {

namespace Far = OpenSubdiv::Far;

UniformRefinement refineUniformly(const SubdivisionCage& cage, int level, bool fullTopologyInLastLevel)
{
    UniformRefinement result{createCageRefiner(cage), std::vector<OsdPoint>(cage.vertexCount())};
    Far::TopologyRefiner::UniformOptions options(level);
    options.fullTopologyInLastLevel = fullTopologyInLastLevel;
    result.refiner->RefineUniform(options);
    for (std::size_t v = 0; v < cage.vertexCount(); ++v)
        result.points[v].p = cage.positions[v];
    const Far::PrimvarRefinerReal<double> primvars(*result.refiner);
    for (int l = 1; l <= level; ++l) {
        std::vector<OsdPoint> next(std::size_t(result.refiner->GetLevel(l).GetNumVertices()));
        OsdPoint* destination = next.data();
        primvars.Interpolate(l, result.points.data(), destination);
        result.points = std::move(next);
    }
    return result;
}

LimitPoints limitOfRefined(const UniformRefinement& refinement)
{
    const std::size_t n = refinement.points.size();
    LimitPoints limit{std::vector<OsdPoint>(n), std::vector<OsdPoint>(n), std::vector<OsdPoint>(n)};
    const Far::PrimvarRefinerReal<double> primvars(*refinement.refiner);
    primvars.Limit(refinement.points, limit.position, limit.du, limit.dv);
    return limit;
}

} // namespace trimlab::test
