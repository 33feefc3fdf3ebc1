#include "core/surface/nurbs_tessellation.h"

#include "core/surface/nurbs_basis.h"
#include "core/surface/nurbs_sampling.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

// Union-find over samples, to merge seam twins and pole samples into one vertex.
struct SampleUnion {
    std::vector<std::size_t> parent;
    explicit SampleUnion(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t(0)); }
    std::size_t find(std::size_t x)
    {
        while (parent[x] != x)
            x = parent[x] = parent[parent[x]];
        return x;
    }
    void join(std::size_t a, std::size_t b)
    {
        a = find(a);
        b = find(b);
        if (a != b)
            parent[std::max(a, b)] = std::min(a, b); // the root is the first sample (row-major)
    }
};

bool sameShape(const NurbsSurface& a, const NurbsSurface& b)
{
    return a.degreeU == b.degreeU && a.degreeV == b.degreeV && a.countU == b.countU && a.countV == b.countV &&
           a.knotsU == b.knotsU && a.knotsV == b.knotsV && a.closedU == b.closedU && a.closedV == b.closedV;
}

} // namespace

NurbsTessellation::NurbsTessellation(const NurbsSurface& surface, int segmentsU, int segmentsV)
{
    requireValidNurbs(surface, "NurbsTessellation");
    if (segmentsU < 1 || segmentsU > kMaxTessellationSegments || segmentsV < 1 || segmentsV > kMaxTessellationSegments)
        throw std::invalid_argument("NurbsTessellation: segment counts must be in 1.." +
                                    std::to_string(kMaxTessellationSegments) + " (got " + std::to_string(segmentsU) +
                                    " × " + std::to_string(segmentsV) + ")");
    m_shape = surface;
    for (const NurbsSide side : {NurbsSide::UBegin, NurbsSide::UEnd, NurbsSide::VBegin, NurbsSide::VEnd})
        m_pole[int(side)] = isPole(surface, side);
    m_controlCount = surface.points.size();
    m_parametersU = tessellationParameters(surface.knotsU, segmentsU, surface.closedU);
    m_parametersV = tessellationParameters(surface.knotsV, segmentsV, surface.closedV);
    if (m_parametersU.size() * m_parametersV.size() > kMaxTessellationSamples)
        throw std::invalid_argument("NurbsTessellation: " + std::to_string(m_parametersU.size()) + " × " +
                                    std::to_string(m_parametersV.size()) + " samples are more than the limit of " +
                                    std::to_string(kMaxTessellationSamples) + "; use fewer segments");
    buildBasisTables();
    buildTopology();
    loadHomogeneous(surface);
    evaluateAll();
}

void NurbsTessellation::buildBasisTables()
{
    const auto build = [](const std::vector<double>& knots, int degree, int count, const std::vector<double>& params,
                          DirectionTable& table) {
        const std::size_t width = std::size_t(degree) + 1;
        table.width = width;
        table.first.resize(params.size());
        table.basis.resize(params.size() * width);
        table.derivative.resize(params.size() * width);
        for (std::size_t a = 0; a < params.size(); ++a) {
            const std::size_t span = findKnotSpan(knots, degree, std::size_t(count), params[a]);
            table.first[a] = std::uint32_t(span - std::size_t(degree));
            basisFunctionsAndDerivatives(knots, degree, span, params[a], {&table.basis[a * width], width},
                                         {&table.derivative[a * width], width});
        }
        // Samples touched by each control column/row: a contiguous range, since the first
        // index never decreases along the samples.
        table.sampleBegin.assign(std::size_t(count), std::uint32_t(params.size()));
        table.sampleEnd.assign(std::size_t(count), 0);
        for (std::size_t a = 0; a < params.size(); ++a)
            for (std::size_t k = 0; k < width; ++k) {
                const std::size_t c = table.first[a] + k;
                table.sampleBegin[c] = std::min(table.sampleBegin[c], std::uint32_t(a));
                table.sampleEnd[c] = std::max(table.sampleEnd[c], std::uint32_t(a + 1));
            }
    };
    build(m_shape.knotsU, m_shape.degreeU, m_shape.countU, m_parametersU, m_tableU);
    build(m_shape.knotsV, m_shape.degreeV, m_shape.countV, m_parametersV, m_tableV);
}

void NurbsTessellation::buildTopology()
{
    const std::size_t nu = m_parametersU.size(), nv = m_parametersV.size();
    SampleUnion samples(nu * nv);
    const auto id = [nu](std::size_t a, std::size_t b) { return b * nu + a; };
    for (std::size_t b = 0; b < nv; ++b) {
        if (m_shape.closedU)
            samples.join(id(0, b), id(nu - 1, b));
        if (m_pole[int(NurbsSide::UBegin)])
            samples.join(id(0, 0), id(0, b));
        if (m_pole[int(NurbsSide::UEnd)])
            samples.join(id(nu - 1, 0), id(nu - 1, b));
    }
    for (std::size_t a = 0; a < nu; ++a) {
        if (m_shape.closedV)
            samples.join(id(a, 0), id(a, nv - 1));
        if (m_pole[int(NurbsSide::VBegin)])
            samples.join(id(0, 0), id(a, 0));
        if (m_pole[int(NurbsSide::VEnd)])
            samples.join(id(0, nv - 1), id(a, nv - 1));
    }
    // Vertices in row-major order of their first sample (the root).
    m_sampleVertex.assign(nu * nv, 0);
    m_vertexSample.clear();
    for (std::size_t s = 0; s < nu * nv; ++s) {
        const std::size_t root = samples.find(s);
        if (root == s) {
            m_sampleVertex[s] = std::uint32_t(m_vertexSample.size());
            m_vertexSample.push_back(s);
        } else {
            m_sampleVertex[s] = m_sampleVertex[root];
        }
    }
    buildTriangles();
    buildPoles();
}

void NurbsTessellation::buildTriangles()
{
    const std::size_t nu = m_parametersU.size(), nv = m_parametersV.size();
    m_mesh.triangles.clear();
    const auto emit = [this](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        if (a != b && b != c && c != a)
            m_mesh.triangles.emplace_back(a, b, c);
    };
    for (std::size_t b = 0; b + 1 < nv; ++b)
        for (std::size_t a = 0; a + 1 < nu; ++a) {
            const std::uint32_t v00 = vertexOfSample(a, b), v10 = vertexOfSample(a + 1, b);
            const std::uint32_t v11 = vertexOfSample(a + 1, b + 1), v01 = vertexOfSample(a, b + 1);
            emit(v00, v10, v11);
            emit(v00, v11, v01);
        }
    m_mesh.positions.assign(m_vertexSample.size(), glm::vec3(0.0f));
    // Vertex → incident triangles (CSR), for pole orientation and fallback normals.
    m_triangleStart.assign(m_vertexSample.size() + 1, 0);
    for (const glm::uvec3& t : m_mesh.triangles)
        for (int k = 0; k < 3; ++k)
            ++m_triangleStart[t[k] + 1];
    std::partial_sum(m_triangleStart.begin(), m_triangleStart.end(), m_triangleStart.begin());
    m_vertexTriangles.assign(m_triangleStart.back(), 0);
    std::vector<std::uint32_t> fill(m_triangleStart.begin(), m_triangleStart.end() - 1);
    for (std::size_t f = 0; f < m_mesh.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k)
            m_vertexTriangles[fill[m_mesh.triangles[f][k]]++] = std::uint32_t(f);
}

void NurbsTessellation::buildPoles()
{
    const std::size_t nu = m_parametersU.size(), nv = m_parametersV.size();
    m_vertexIsPole.assign(m_vertexSample.size(), 0);
    m_poles.clear();
    const auto add = [&](NurbsSide side, std::size_t a, std::size_t b, bool alongU) {
        if (!m_pole[int(side)])
            return;
        Pole pole;
        pole.vertex = vertexOfSample(a, b);
        pole.alongU = alongU;
        const std::size_t n = alongU ? nu : nv;
        for (std::size_t k = 0; k < n; ++k)
            pole.samples.push_back(alongU ? b * nu + k : k * nu + a);
        m_vertexIsPole[pole.vertex] = 1;
        m_poles.push_back(std::move(pole));
    };
    add(NurbsSide::VBegin, 0, 0, true);
    add(NurbsSide::VEnd, 0, nv - 1, true);
    add(NurbsSide::UBegin, 0, 0, false);
    add(NurbsSide::UEnd, nu - 1, 0, false);
}

glm::dvec2 NurbsTessellation::vertexParameters(std::uint32_t vertex) const
{
    const std::size_t s = m_vertexSample.at(vertex);
    const std::size_t nu = m_parametersU.size();
    return {m_parametersU[s % nu], m_parametersV[s / nu]};
}

bool NurbsTessellation::isPoleVertex(std::uint32_t vertex) const
{
    return vertex < m_vertexIsPole.size() && m_vertexIsPole[vertex] != 0;
}

bool NurbsTessellation::matches(const NurbsSurface& surface) const
{
    if (!sameShape(surface, m_shape) || surface.points.size() != m_controlCount ||
        surface.weights.size() != m_controlCount)
        return false;
    for (const NurbsSide side : {NurbsSide::UBegin, NurbsSide::UEnd, NurbsSide::VBegin, NurbsSide::VEnd})
        if (isPole(surface, side) != m_pole[int(side)])
            return false;
    return true;
}

void NurbsTessellation::requireUpdatable(const NurbsSurface& surface) const
{
    if (!sameShape(surface, m_shape) || surface.points.size() != m_controlCount ||
        surface.weights.size() != m_controlCount)
        throw std::invalid_argument("NurbsTessellation::update: the surface has other degrees, counts, knots or closed "
                                    "flags than the tessellation; build a new NurbsTessellation");
    if (const auto found = findNurbsProblem(surface))
        throw std::invalid_argument("NurbsTessellation::update: " + found->where + ": " + found->reason);
    for (const NurbsSide side : {NurbsSide::UBegin, NurbsSide::UEnd, NurbsSide::VBegin, NurbsSide::VEnd})
        if (isPole(surface, side) != m_pole[int(side)])
            throw std::invalid_argument(std::string("NurbsTessellation::update: ") +
                                        (m_pole[int(side)] ? "a pole was split (one of its control points moved "
                                                             "alone); move pole points with moveControlPoint"
                                                           : "a boundary collapsed into a pole; build a new "
                                                             "NurbsTessellation"));
}

void NurbsTessellation::loadHomogeneous(const NurbsSurface& surface)
{
    m_homogeneous.resize(m_controlCount);
    for (std::size_t c = 0; c < m_controlCount; ++c)
        m_homogeneous[c] = glm::dvec4(surface.points[c] * surface.weights[c], surface.weights[c]);
    m_derivativeFloor = nurbsDerivativeFloor(surface);
}

std::size_t NurbsTessellation::tableBytes() const
{
    const auto bytes = [](const DirectionTable& t) {
        return (t.basis.size() + t.derivative.size()) * sizeof(double) +
               (t.first.size() + t.sampleBegin.size() + t.sampleEnd.size()) * sizeof(std::uint32_t);
    };
    return bytes(m_tableU) + bytes(m_tableV) + m_sampleVertex.size() * sizeof(std::uint32_t) +
           m_vertexSample.size() * sizeof(std::size_t) + m_vertexTriangles.size() * sizeof(std::uint32_t) +
           m_triangleStart.size() * sizeof(std::uint32_t);
}

} // namespace trimlab
