#include "core/surface/subdivision_refinement.h"

#include "core/surface/cage_refiner.h"

#include <opensubdiv/far/ptexIndices.h>
#include <opensubdiv/far/stencilTable.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyLevel.h>

#include <glm/vec2.hpp>

#include <algorithm>
#include <array>
#include <memory>

namespace trimlab {

namespace {

namespace Far = OpenSubdiv::Far;

} // namespace

void appendStencilRow(SubdivisionSurface::StencilRows& rows, std::vector<StencilWeight>& row)
{
    std::sort(row.begin(), row.end(),
              [](const StencilWeight& a, const StencilWeight& b) { return a.cageVertex < b.cageVertex; });
    for (std::size_t i = 0; i < row.size();) {
        StencilWeight merged = row[i];
        for (++i; i < row.size() && row[i].cageVertex == merged.cageVertex; ++i)
            merged.weight += row[i].weight;
        if (merged.weight != 0.0)
            rows.entries.push_back(merged);
    }
    rows.offsets.push_back(rows.entries.size());
}

namespace {

SubdivisionSurface::StencilRows identityRows(std::size_t count)
{
    SubdivisionSurface::StencilRows rows;
    for (std::size_t v = 0; v < count; ++v) {
        rows.entries.push_back({std::uint32_t(v), 1.0});
        rows.offsets.push_back(rows.entries.size());
    }
    return rows;
}

SubdivisionSurface::StencilRows uniformStencils(const Far::TopologyRefiner& refiner, std::size_t cageVertices)
{
    const int level = refiner.GetMaxLevel();
    if (level == 0)
        return identityRows(cageVertices);
    Far::StencilTableFactoryReal<double>::Options options;
    options.generateIntermediateLevels = false; // the finest level only, factorized to the cage
    options.generateOffsets = true;
    const std::unique_ptr<const Far::StencilTableReal<double>> table(
        Far::StencilTableFactoryReal<double>::Create(refiner, options));
    if (!table || table->GetNumStencils() != refiner.GetLevel(level).GetNumVertices())
        throw SubdivisionError("OpenSubdiv built no stencils for the refined cage");
    SubdivisionSurface::StencilRows rows;
    std::vector<StencilWeight> row;
    for (int s = 0; s < table->GetNumStencils(); ++s) {
        const auto stencil = table->GetStencil(Far::Index(s));
        row.clear();
        for (int k = 0; k < stencil.GetSize(); ++k)
            row.push_back({std::uint32_t(stencil.GetVertexIndices()[k]), stencil.GetWeights()[k]});
        appendStencilRow(rows, row);
    }
    return rows;
}

// Quads as (a,b,c) + (a,c,d); larger level-0 polygons as fans (their output vertices are the
// cage vertices, so a fan is all a fixed connectivity can do).
std::vector<glm::uvec3> refinedTriangles(const Far::TopologyLevel& level)
{
    std::vector<glm::uvec3> triangles;
    triangles.reserve(std::size_t(level.GetNumFaces()) * 2);
    for (int f = 0; f < level.GetNumFaces(); ++f) {
        const Far::ConstIndexArray v = level.GetFaceVertices(f);
        for (int k = 1; k + 1 < v.size(); ++k)
            triangles.emplace_back(unsigned(v[0]), unsigned(v[k]), unsigned(v[k + 1]));
    }
    return triangles;
}

// A face of some refinement level and where its corners lie in ptex space.
struct FaceDomain {
    int ptexFace = -1; // -1: a level-0 n-gon (Catmull–Clark, n ≠ 4), split into sub-faces at level 1
    std::array<glm::dvec2, 4> corner{};
};

// The ptex domains of the level-0 faces. A regular face (quad, or Loop triangle) is one ptex
// face with corners (0,0), (1,0), (1,1), (0,1) (triangles: (0,0), (1,0), (0,1)).
std::vector<FaceDomain> baseDomains(const Far::TopologyRefiner& refiner, const Far::PtexIndices& ptex)
{
    const Far::TopologyLevel& base = refiner.GetLevel(0);
    const int regular = refiner.GetSchemeType() == OpenSubdiv::Sdc::SCHEME_LOOP ? 3 : 4;
    std::vector<FaceDomain> domains(std::size_t(base.GetNumFaces()));
    for (int f = 0; f < base.GetNumFaces(); ++f) {
        if (base.GetFaceVertices(f).size() != regular)
            continue;
        FaceDomain& d = domains[std::size_t(f)];
        d.ptexFace = ptex.GetFaceId(f);
        d.corner = regular == 4 ? std::array<glm::dvec2, 4>{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}
                                : std::array<glm::dvec2, 4>{{{0, 0}, {1, 0}, {0, 1}, {0, 0}}};
    }
    return domains;
}

// Where `vertex`, a child of parent face f, lies in ptex space: in the parent's frame, or
// for a level-0 n-gon (pd.ptexFace < 0) in the frame of the sub-face of `corner`: the
// corner's child at (0,0), the next edge's midpoint at (1,0), the face centre at (1,1),
// the previous edge's midpoint at (0,1).
glm::dvec2 childCoordinate(const Far::TopologyLevel& parent, int f, Far::Index faceChild, const FaceDomain& pd,
                           int corner, Far::Index vertex)
{
    const Far::ConstIndexArray fv = parent.GetFaceVertices(f);
    const Far::ConstIndexArray fe = parent.GetFaceEdges(f);
    const int n = fv.size();
    if (pd.ptexFace < 0) { // n-gon sub-face; pd.corner is unused (it has room for 4 only)
        if (vertex == faceChild)
            return glm::dvec2(1, 1);
        for (int k = 0; k < n; ++k) {
            if (vertex == parent.GetVertexChildVertex(fv[k]))
                return glm::dvec2(0, 0);
            if (vertex == parent.GetEdgeChildVertex(fe[k]))
                return k == corner ? glm::dvec2(1, 0) : glm::dvec2(0, 1);
        }
        return glm::dvec2(0.0);
    }
    if (vertex == faceChild) // a quad's centre (Loop has no face points)
        return 0.25 * (pd.corner[0] + pd.corner[1] + pd.corner[2] + pd.corner[3]);
    for (int k = 0; k < n; ++k) {
        const glm::dvec2 a = pd.corner[std::size_t(k)];
        const glm::dvec2 b = pd.corner[std::size_t((k + 1) % n)];
        if (vertex == parent.GetVertexChildVertex(fv[k]))
            return a;
        if (vertex == parent.GetEdgeChildVertex(fe[k]))
            return 0.5 * (a + b);
    }
    return glm::dvec2(0.0); // not a child of f: cannot happen for Far's child faces
}

std::vector<FaceDomain> childDomains(const Far::TopologyRefiner& refiner, int level, const Far::PtexIndices& ptex,
                                     const std::vector<FaceDomain>& parents)
{
    const Far::TopologyLevel& parent = refiner.GetLevel(level);
    const Far::TopologyLevel& child = refiner.GetLevel(level + 1);
    std::vector<FaceDomain> domains(std::size_t(child.GetNumFaces()));
    const bool loop = refiner.GetSchemeType() == OpenSubdiv::Sdc::SCHEME_LOOP;
    for (int f = 0; f < parent.GetNumFaces(); ++f) {
        const FaceDomain& pd = parents[std::size_t(f)];
        const Far::ConstIndexArray fv = parent.GetFaceVertices(f);
        const int n = fv.size();
        // Loop refinement adds no face points (and Far keeps no face-child table for it).
        const Far::Index faceChild = loop ? Far::INDEX_INVALID : parent.GetFaceChildVertex(f);
        for (const Far::Index c : parent.GetFaceChildFaces(f)) {
            const Far::ConstIndexArray cv = child.GetFaceVertices(c);
            FaceDomain& d = domains[std::size_t(c)];
            // Which parent corner's child vertex this child face holds (n-gon sub-faces).
            int corner = -1;
            for (int k = 0; k < n && corner < 0; ++k)
                if (std::find(cv.begin(), cv.end(), parent.GetVertexChildVertex(fv[k])) != cv.end())
                    corner = k;
            d.ptexFace = pd.ptexFace < 0 ? ptex.GetFaceId(f) + corner : pd.ptexFace;
            for (int i = 0; i < cv.size(); ++i)
                d.corner[std::size_t(i)] = childCoordinate(parent, f, faceChild, pd, corner, cv[i]);
        }
    }
    return domains;
}

// The ptex location of every vertex of the finest level, taken from the first face using it.
std::vector<LimitLocation> vertexLocations(const Far::TopologyRefiner& refiner)
{
    const Far::PtexIndices ptex(refiner);
    std::vector<FaceDomain> domains = baseDomains(refiner, ptex);
    const int levels = refiner.GetMaxLevel();
    for (int level = 0; level < levels; ++level)
        domains = childDomains(refiner, level, ptex, domains);
    const Far::TopologyLevel& finest = refiner.GetLevel(levels);
    std::vector<LimitLocation> locations(std::size_t(finest.GetNumVertices()), LimitLocation{~0u, 0.0, 0.0});
    for (int f = 0; f < finest.GetNumFaces(); ++f) {
        const FaceDomain& d = domains[std::size_t(f)];
        const Far::ConstIndexArray fv = finest.GetFaceVertices(f);
        for (int k = 0; k < fv.size(); ++k) {
            LimitLocation& l = locations[std::size_t(fv[k])];
            if (l.ptexFace != ~0u)
                continue;
            if (d.ptexFace < 0) // a level-0 n-gon: its corner k is the origin of sub-face k
                l = {std::uint32_t(ptex.GetFaceId(f) + k), 0.0, 0.0};
            else
                l = {std::uint32_t(d.ptexFace), d.corner[std::size_t(k)].x, d.corner[std::size_t(k)].y};
        }
    }
    return locations;
}

} // namespace

std::size_t predictedTriangleCount(const SubdivisionCage& cage, int level)
{
    const std::size_t grow = std::size_t(1) << (2 * level); // 4^level
    std::size_t total = 0;
    for (const std::uint32_t n : cage.faceSizes) {
        if (cage.scheme == SubdivisionScheme::Loop || level == 0)
            total += (cage.scheme == SubdivisionScheme::Loop ? 1 : n - 2) * grow;
        else
            total += 2 * (n == 4 ? grow : n * (grow / 4));
    }
    return total;
}

SubdivisionTables buildSubdivisionTables(const SubdivisionCage& cage, SubdivisionSettings settings)
{
    const std::unique_ptr<Far::TopologyRefiner> refiner = createCageRefiner(cage);
    if (settings.level > 0) {
        Far::TopologyRefiner::UniformOptions options(settings.level);
        options.fullTopologyInLastLevel = true;
        refiner->RefineUniform(options);
    }
    SubdivisionTables tables;
    const Far::TopologyLevel& finest = refiner->GetLevel(settings.level);
    tables.outputVertexCount = std::size_t(finest.GetNumVertices());
    tables.triangles = refinedTriangles(finest);
    if (settings.mode == SubdivisionMode::Uniform) {
        tables.position = uniformStencils(*refiner, cage.vertexCount());
        return tables;
    }
    tables.locations = vertexLocations(*refiner);
    buildLimitStencils(cage, tables.locations, tables);
    return tables;
}

} // namespace trimlab
