// The re-evaluation half of NurbsTessellation: sparse mat-vecs over the tables that
// nurbs_tessellation.cpp builds, normals (regular, pole limit, fallback), and supports.
#include "core/surface/nurbs_tessellation.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

glm::dvec3 normalizedOrZero(const glm::dvec3& v)
{
    const double l = glm::length(v);
    return l > 0.0 && std::isfinite(l) ? v / l : glm::dvec3(0.0);
}

} // namespace

void NurbsTessellation::storeSample(std::size_t sample, const glm::dvec4& a, const glm::dvec4& au, const glm::dvec4& av)
{
    // Rational quotient rule, written exactly as evaluateNurbs writes it.
    const glm::dvec3 position = glm::dvec3(a) / a.w;
    m_sampleDu[sample] = (glm::dvec3(au) - au.w * position) / a.w;
    m_sampleDv[sample] = (glm::dvec3(av) - av.w * position) / a.w;
    const std::uint32_t vertex = m_sampleVertex[sample];
    if (m_vertexSample[vertex] == sample) {
        m_positions[vertex] = position;
        m_mesh.positions[vertex] = glm::vec3(position);
    }
}

void NurbsTessellation::evaluateAll()
{
    const std::size_t nu = m_parametersU.size(), nv = m_parametersV.size();
    const std::size_t countU = std::size_t(m_shape.countU), countV = std::size_t(m_shape.countV);
    const std::size_t pu = m_tableU.width, pv = m_tableV.width;
    m_sampleDu.resize(nu * nv);
    m_sampleDv.resize(nu * nv);
    m_positions.resize(m_vertexSample.size());
    m_normals.resize(m_vertexSample.size());
    // Pass 1: every u sample against every control row (the iso-v control curves).
    m_rowSums.assign(nu * countV, glm::dvec4(0.0));
    m_rowSumsDu.assign(nu * countV, glm::dvec4(0.0));
    for (std::size_t j = 0; j < countV; ++j)
        for (std::size_t a = 0; a < nu; ++a) {
            const glm::dvec4* h = &m_homogeneous[j * countU + m_tableU.first[a]];
            const double* n = &m_tableU.basis[a * pu];
            const double* d = &m_tableU.derivative[a * pu];
            glm::dvec4 row(0.0), rowDu(0.0);
            for (std::size_t k = 0; k < pu; ++k) {
                row += n[k] * h[k];
                rowDu += d[k] * h[k];
            }
            m_rowSums[a * countV + j] = row;
            m_rowSumsDu[a * countV + j] = rowDu;
        }
    // Pass 2: every sample from the q+1 row sums of its v span.
    for (std::size_t b = 0; b < nv; ++b) {
        const std::size_t firstV = m_tableV.first[b];
        const double* n = &m_tableV.basis[b * pv];
        const double* d = &m_tableV.derivative[b * pv];
        for (std::size_t a = 0; a < nu; ++a) {
            const glm::dvec4* row = &m_rowSums[a * countV + firstV];
            const glm::dvec4* rowDu = &m_rowSumsDu[a * countV + firstV];
            glm::dvec4 s(0.0), su(0.0), sv(0.0);
            for (std::size_t l = 0; l < pv; ++l) {
                s += n[l] * row[l];
                su += n[l] * rowDu[l];
                sv += d[l] * row[l];
            }
            storeSample(b * nu + a, s, su, sv);
        }
    }
    for (std::uint32_t v = 0; v < m_vertexSample.size(); ++v)
        updateNormal(v);
}

void NurbsTessellation::evaluateSample(std::size_t sample)
{
    const std::size_t nu = m_parametersU.size();
    const std::size_t a = sample % nu, b = sample / nu;
    const std::size_t countU = std::size_t(m_shape.countU);
    const std::size_t pu = m_tableU.width, pv = m_tableV.width;
    const double* nU = &m_tableU.basis[a * pu];
    const double* dU = &m_tableU.derivative[a * pu];
    const double* nV = &m_tableV.basis[b * pv];
    const double* dV = &m_tableV.derivative[b * pv];
    glm::dvec4 s(0.0), su(0.0), sv(0.0);
    for (std::size_t l = 0; l < pv; ++l) {
        const glm::dvec4* h = &m_homogeneous[(m_tableV.first[b] + l) * countU + m_tableU.first[a]];
        glm::dvec4 row(0.0), rowDu(0.0);
        for (std::size_t k = 0; k < pu; ++k) {
            row += nU[k] * h[k];
            rowDu += dU[k] * h[k];
        }
        s += nV[l] * row;
        su += nV[l] * rowDu;
        sv += dV[l] * row;
    }
    storeSample(sample, s, su, sv);
}

glm::dvec3 NurbsTessellation::fanNormal(std::uint32_t vertex, bool unitFaces) const
{
    glm::dvec3 sum(0.0);
    for (std::uint32_t k = m_triangleStart[vertex]; k < m_triangleStart[vertex + 1]; ++k) {
        const glm::uvec3& t = m_mesh.triangles[m_vertexTriangles[k]];
        const glm::dvec3 n = glm::cross(m_positions[t[1]] - m_positions[t[0]], m_positions[t[2]] - m_positions[t[0]]);
        sum += unitFaces ? normalizedOrZero(n) : n;
    }
    return sum;
}

glm::dvec3 NurbsTessellation::poleNormal(const Pole& pole) const
{
    // The derivatives across the side span the tangent plane at the pole; Newell's sum of
    // their consecutive cross products is its normal, up to orientation.
    const std::vector<glm::dvec3>& across = pole.alongU ? m_sampleDv : m_sampleDu;
    glm::dvec3 sum(0.0);
    double scale = 0.0;
    for (std::size_t k = 0; k + 1 < pole.samples.size(); ++k) {
        const glm::dvec3& d0 = across[pole.samples[k]];
        const glm::dvec3& d1 = across[pole.samples[k + 1]];
        sum += glm::cross(d0, d1);
        scale += glm::length(d0) * glm::length(d1);
    }
    const glm::dvec3 fan = fanNormal(pole.vertex, false);
    if (!(glm::length(sum) > 1e-10 * scale))
        return normalizedOrZero(fan);
    return normalizedOrZero(glm::dot(sum, fan) < 0.0 ? -sum : sum);
}

void NurbsTessellation::updateNormal(std::uint32_t vertex)
{
    glm::dvec3 normal(0.0);
    if (m_vertexIsPole[vertex]) {
        for (const Pole& pole : m_poles)
            if (pole.vertex == vertex) {
                normal = poleNormal(pole);
                break;
            }
    } else {
        const std::size_t s = m_vertexSample[vertex];
        const std::optional<glm::dvec3> regular = regularNurbsNormal(m_sampleDu[s], m_sampleDv[s], m_derivativeFloor);
        normal = regular ? *regular : normalizedOrZero(fanNormal(vertex, true));
    }
    m_normals[vertex] = glm::vec3(normal);
}

void NurbsTessellation::update(const NurbsSurface& surface)
{
    requireUpdatable(surface);
    loadHomogeneous(surface);
    evaluateAll();
}

std::vector<std::size_t> NurbsTessellation::tiedGroup(std::span<const std::size_t> changed) const
{
    std::vector<std::size_t> group;
    for (const std::size_t c : changed) {
        if (c >= m_controlCount)
            throw std::out_of_range("NurbsTessellation: control point " + std::to_string(c) +
                                    " does not exist (the surface has " + std::to_string(m_controlCount) + ")");
        const std::vector<std::size_t> linked = linkedControlPoints(m_shape, c);
        group.insert(group.end(), linked.begin(), linked.end());
    }
    std::sort(group.begin(), group.end());
    group.erase(std::unique(group.begin(), group.end()), group.end());
    return group;
}

std::vector<std::uint32_t> NurbsTessellation::supportOf(std::span<const std::size_t> group) const
{
    const std::size_t nu = m_parametersU.size();
    const std::size_t countU = std::size_t(m_shape.countU);
    // A mark per vertex rather than sort + unique: a big edit touches each vertex up to
    // (p+1)(q+1) times.
    std::vector<std::uint8_t> marked(m_vertexSample.size(), 0);
    std::size_t count = 0;
    for (const std::size_t c : group) {
        const std::size_t i = c % countU, j = c / countU;
        for (std::size_t b = m_tableV.sampleBegin[j]; b < m_tableV.sampleEnd[j]; ++b) {
            if (m_tableV.basis[b * m_tableV.width + (j - m_tableV.first[b])] == 0.0)
                continue;
            for (std::size_t a = m_tableU.sampleBegin[i]; a < m_tableU.sampleEnd[i]; ++a) {
                if (m_tableU.basis[a * m_tableU.width + (i - m_tableU.first[a])] == 0.0)
                    continue;
                const std::size_t s = b * nu + a;
                const std::uint32_t v = m_sampleVertex[s];
                if (m_vertexSample[v] == s && !marked[v]) {
                    marked[v] = 1;
                    ++count;
                }
            }
        }
    }
    std::vector<std::uint32_t> vertices;
    vertices.reserve(count);
    for (std::uint32_t v = 0; v < marked.size(); ++v)
        if (marked[v])
            vertices.push_back(v);
    return vertices;
}

std::vector<std::uint32_t> NurbsTessellation::support(std::size_t controlIndex) const
{
    const std::size_t one[1] = {controlIndex};
    return supportOf(tiedGroup(one));
}

std::vector<std::uint32_t> NurbsTessellation::update(const NurbsSurface& surface, std::span<const std::size_t> changed)
{
    const std::vector<std::size_t> group = tiedGroup(changed);
    requireUpdatable(surface);
    for (const std::size_t c : group)
        m_homogeneous[c] = glm::dvec4(surface.points[c] * surface.weights[c], surface.weights[c]);
    // Every sample whose spans include a changed point: a rectangle of samples per point.
    const std::size_t nu = m_parametersU.size();
    const std::size_t countU = std::size_t(m_shape.countU);
    std::size_t area = 0;
    for (const std::size_t c : group)
        area += std::size_t(m_tableU.sampleEnd[c % countU] - m_tableU.sampleBegin[c % countU]) *
                std::size_t(m_tableV.sampleEnd[c / countU] - m_tableV.sampleBegin[c / countU]);
    if (area >= sampleCount() / 2) {
        // Most of the surface changed: the separable full pass is cheaper and, summing in
        // the same order, gives the same bits for every sample.
        evaluateAll();
        return supportOf(group);
    }
    m_sampleMark.resize(nu * m_parametersV.size(), 0);
    std::vector<std::size_t> samples;
    for (const std::size_t c : group) {
        const std::size_t i = c % countU, j = c / countU;
        for (std::size_t b = m_tableV.sampleBegin[j]; b < m_tableV.sampleEnd[j]; ++b)
            for (std::size_t a = m_tableU.sampleBegin[i]; a < m_tableU.sampleEnd[i]; ++a)
                if (!m_sampleMark[b * nu + a]) {
                    m_sampleMark[b * nu + a] = 1;
                    samples.push_back(b * nu + a);
                }
    }
    for (const std::size_t s : samples)
        evaluateSample(s);
    std::vector<std::uint32_t> normalVertices;
    for (const std::size_t s : samples) {
        normalVertices.push_back(m_sampleVertex[s]);
        m_sampleMark[s] = 0;
    }
    std::sort(normalVertices.begin(), normalVertices.end());
    normalVertices.erase(std::unique(normalVertices.begin(), normalVertices.end()), normalVertices.end());
    for (const std::uint32_t v : normalVertices)
        updateNormal(v);
    return supportOf(group);
}

} // namespace trimlab
