#include "core/mesh/loop_subdivision.h"

#include "core/util/memory_budget.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefiner.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <glm/vec3.hpp>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace trimlab {

namespace {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

// The primvar type PrimvarRefiner blends: a position in double precision.
struct SubdivisionPoint {
    glm::dvec3 p{0.0};

    void Clear(void* = nullptr) { p = glm::dvec3(0.0); }
    void AddWithWeight(const SubdivisionPoint& source, double weight) { p += weight * source.p; }
};

void requireSubdividable(const TriangleMesh& mesh, int levels)
{
    if (levels < 0 || levels > 15)
        throw std::invalid_argument("Loop subdivision: " + std::to_string(levels) + " levels (use 0 to 15)");
    const double triangles = double(mesh.triangleCount()) * std::pow(4.0, levels);
    if (triangles > double(kMaxSubdividedTriangles))
        throw std::invalid_argument("Loop subdivision: " + std::to_string(levels) + " levels of " +
                                    std::to_string(mesh.triangleCount()) + " triangles would make " +
                                    std::to_string(std::llround(triangles)) + " (at most " +
                                    std::to_string(kMaxSubdividedTriangles) + "); use fewer levels");
    // About 160 bytes per final triangle: its indices and half a vertex in the result, the
    // double-precision points of every level and OpenSubdiv's refined topology.
    requireMemory(std::uint64_t(triangles) * 160,
                  "Loop subdivision to " + std::to_string(std::llround(triangles)) + " triangles", "use fewer levels");
    for (std::size_t f = 0; f < mesh.triangleCount(); ++f) {
        const glm::uvec3& t = mesh.triangles[f];
        if (t.x >= mesh.vertexCount() || t.y >= mesh.vertexCount() || t.z >= mesh.vertexCount())
            throw std::invalid_argument("Loop subdivision: triangle " + std::to_string(f) + " names a vertex ≥ " +
                                        std::to_string(mesh.vertexCount()));
        if (t.x == t.y || t.y == t.z || t.z == t.x)
            throw std::invalid_argument("Loop subdivision: triangle " + std::to_string(f) +
                                        " repeats a vertex; remove degenerate faces first");
    }
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const glm::vec3& p = mesh.positions[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::invalid_argument("Loop subdivision: vertex " + std::to_string(v) + " is not finite");
    }
}

std::unique_ptr<Far::TopologyRefiner> loopRefiner(const TriangleMesh& mesh)
{
    const std::vector<int> verticesPerFace(mesh.triangleCount(), 3);
    std::vector<Far::Index> indices;
    indices.reserve(3 * mesh.triangleCount());
    for (const glm::uvec3& t : mesh.triangles)
        indices.insert(indices.end(), {Far::Index(t.x), Far::Index(t.y), Far::Index(t.z)});
    Far::TopologyDescriptor descriptor;
    descriptor.numVertices = int(mesh.vertexCount());
    descriptor.numFaces = int(mesh.triangleCount());
    descriptor.numVertsPerFace = verticesPerFace.data();
    descriptor.vertIndicesPerFace = indices.data();
    Sdc::Options options;
    options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    std::unique_ptr<Far::TopologyRefiner> refiner(
        Factory::Create(descriptor, Factory::Options(Sdc::SCHEME_LOOP, options)));
    if (!refiner)
        throw std::runtime_error("Loop subdivision: OpenSubdiv refused the mesh's topology");
    return refiner;
}

} // namespace

TriangleMesh loopSubdivide(const TriangleMesh& mesh, int levels)
{
    requireSubdividable(mesh, levels);
    if (levels == 0 || mesh.empty())
        return mesh;
    const std::unique_ptr<Far::TopologyRefiner> refiner = loopRefiner(mesh);
    refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(levels));
    std::vector<SubdivisionPoint> current(mesh.vertexCount());
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
        current[v].p = glm::dvec3(mesh.positions[v]);
    const Far::PrimvarRefinerReal<double> interpolator(*refiner);
    for (int level = 1; level <= levels; ++level) {
        std::vector<SubdivisionPoint> next(std::size_t(refiner->GetLevel(level).GetNumVertices()));
        SubdivisionPoint* destination = next.data();
        interpolator.Interpolate(level, current.data(), destination);
        current = std::move(next);
    }
    const Far::TopologyLevel& last = refiner->GetLevel(levels);
    TriangleMesh result;
    result.positions.reserve(current.size());
    for (const SubdivisionPoint& point : current)
        result.positions.emplace_back(point.p);
    result.triangles.reserve(std::size_t(last.GetNumFaces()));
    for (int f = 0; f < last.GetNumFaces(); ++f) {
        const Far::ConstIndexArray v = last.GetFaceVertices(f);
        result.triangles.emplace_back(unsigned(v[0]), unsigned(v[1]), unsigned(v[2]));
    }
    return result;
}

} // namespace trimlab
