#include "core/surface/cage_refiner.h"
#include "core/surface/subdivision_refinement.h"

#include <opensubdiv/far/patchTable.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/stencilTable.h>
#include <opensubdiv/far/stencilTableFactory.h>

#include <algorithm>
#include <memory>

namespace trimlab {

namespace {

namespace Far = OpenSubdiv::Far;
using StencilTable = Far::StencilTableReal<double>;
using StencilFactory = Far::StencilTableFactoryReal<double>;
using LimitFactory = Far::LimitStencilTableFactoryReal<double>;

// Stencils of every refined vertex (all levels, the cage vertices included as unit rows),
// factorized to the cage, with the patch table's local points (Gregory end caps) appended:
// what LimitStencilTableFactory needs to express patch evaluations over cage vertices.
std::unique_ptr<const StencilTable> refinedAndLocalStencils(const Far::TopologyRefiner& refiner,
                                                            const Far::PatchTable& patches)
{
    StencilFactory::Options options;
    options.generateIntermediateLevels = true;
    options.generateControlVerts = true;
    options.generateOffsets = true;
    std::unique_ptr<const StencilTable> refined(StencilFactory::Create(refiner, options));
    const StencilTable* local = patches.GetLocalPointStencilTable<double>();
    if (!local || local->GetNumStencils() == 0)
        return refined;
    return std::unique_ptr<const StencilTable>(
        StencilFactory::AppendLocalPointStencilTable(refiner, refined.get(), local));
}

void appendRow(SubdivisionSurface::StencilRows& rows, const Far::Index* indices, const double* weights, int size,
               std::size_t cageVertices, std::vector<StencilWeight>& scratch)
{
    scratch.clear();
    for (int k = 0; k < size; ++k) {
        if (std::size_t(indices[k]) >= cageVertices) // must be factorized down to the cage
            throw SubdivisionError("OpenSubdiv returned a limit stencil over refined vertices");
        scratch.push_back({std::uint32_t(indices[k]), weights[k]});
    }
    appendStencilRow(rows, scratch);
}

} // namespace

void buildLimitStencils(const SubdivisionCage& cage, const std::vector<LimitLocation>& locations,
                        SubdivisionTables& tables)
{
    const std::unique_ptr<Far::TopologyRefiner> refiner = createCageRefiner(cage);
    const Far::PatchTableFactory::Options patchOptions = limitPatchOptions();
    refiner->RefineAdaptive(patchOptions.GetRefineAdaptiveOptions());
    const std::unique_ptr<const Far::PatchTable> patches(Far::PatchTableFactory::Create(*refiner, patchOptions));
    const std::unique_ptr<const StencilTable> cvStencils = refinedAndLocalStencils(*refiner, *patches);

    // One location array per output vertex keeps the stencils in output order.
    std::vector<double> u(locations.size()), v(locations.size());
    LimitFactory::LocationArrayVec arrays(locations.size());
    for (std::size_t i = 0; i < locations.size(); ++i) {
        u[i] = locations[i].u;
        v[i] = locations[i].v;
        arrays[i].ptexIdx = int(locations[i].ptexFace);
        arrays[i].numLocations = 1;
        arrays[i].s = &u[i];
        arrays[i].t = &v[i];
    }
    LimitFactory::Options options;
    options.generate1stDerivatives = true;
    const std::unique_ptr<const Far::LimitStencilTableReal<double>> limit(
        LimitFactory::Create(*refiner, arrays, cvStencils.get(), patches.get(), options));
    if (!limit || std::size_t(limit->GetNumStencils()) != locations.size())
        throw SubdivisionError("OpenSubdiv found no limit surface point for some output vertices (" +
                               std::to_string(limit ? limit->GetNumStencils() : 0) + " of " +
                               std::to_string(locations.size()) + ")");
    const std::vector<int>& sizes = limit->GetSizes();
    const std::vector<Far::Index>& offsets = limit->GetOffsets();
    const std::vector<Far::Index>& indices = limit->GetControlIndices();
    std::vector<StencilWeight> scratch;
    for (std::size_t s = 0; s < locations.size(); ++s) {
        const std::size_t o = std::size_t(offsets[s]);
        appendRow(tables.position, &indices[o], &limit->GetWeights()[o], sizes[s], cage.vertexCount(), scratch);
        appendRow(tables.tangentU, &indices[o], &limit->GetDuWeights()[o], sizes[s], cage.vertexCount(), scratch);
        appendRow(tables.tangentV, &indices[o], &limit->GetDvWeights()[o], sizes[s], cage.vertexCount(), scratch);
    }
}

} // namespace trimlab
