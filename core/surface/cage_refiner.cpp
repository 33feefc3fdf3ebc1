#include "core/surface/cage_refiner.h"

#include "core/surface/subdivision_surface.h"

#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <vector>

namespace trimlab {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

std::unique_ptr<Far::TopologyRefiner> createCageRefiner(const SubdivisionCage& cage)
{
    const std::vector<int> sizes(cage.faceSizes.begin(), cage.faceSizes.end());
    const std::vector<Far::Index> indices(cage.faceIndices.begin(), cage.faceIndices.end());
    std::vector<Far::Index> creasePairs;
    std::vector<float> creaseWeights;
    for (const CageCrease& c : cage.creases) {
        creasePairs.insert(creasePairs.end(), {Far::Index(c.a), Far::Index(c.b)});
        creaseWeights.push_back(c.sharpness);
    }
    std::vector<Far::Index> cornerVertices;
    std::vector<float> cornerWeights;
    for (const CageCorner& c : cage.corners) {
        cornerVertices.push_back(Far::Index(c.vertex));
        cornerWeights.push_back(c.sharpness);
    }
    Far::TopologyDescriptor descriptor;
    descriptor.numVertices = int(cage.vertexCount());
    descriptor.numFaces = int(cage.faceCount());
    descriptor.numVertsPerFace = sizes.data();
    descriptor.vertIndicesPerFace = indices.data();
    descriptor.numCreases = int(cage.creases.size());
    descriptor.creaseVertexIndexPairs = creasePairs.data();
    descriptor.creaseWeights = creaseWeights.data();
    descriptor.numCorners = int(cage.corners.size());
    descriptor.cornerVertexIndices = cornerVertices.data();
    descriptor.cornerWeights = cornerWeights.data();

    Sdc::Options options;
    options.SetVtxBoundaryInterpolation(cage.boundary == BoundaryInterpolation::EdgesOnly
                                            ? Sdc::Options::VTX_BOUNDARY_EDGE_ONLY
                                            : Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
    const Sdc::SchemeType scheme = cage.scheme == SubdivisionScheme::Loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK;
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(descriptor, Factory::Options(scheme, options)));
    if (!refiner)
        throw SubdivisionError("OpenSubdiv refused the cage's topology (" + std::to_string(cage.vertexCount()) +
                               " vertices, " + std::to_string(cage.faceCount()) +
                               " faces); check it for non-manifold edges or vertices");
    return refiner;
}

Far::PatchTableFactory::Options limitPatchOptions()
{
    Far::PatchTableFactory::Options options(SubdivisionSurface::kLimitIsolationLevel);
    options.useInfSharpPatch = true;
    options.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
    options.SetPatchPrecision<double>();
    options.generateVaryingTables = false;
    options.generateVaryingLocalPoints = false;
    options.generateFVarTables = false;
    return options;
}

} // namespace trimlab
