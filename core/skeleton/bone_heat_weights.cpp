#include "core/skeleton/bone_heat_weights.h"

#include "core/skeleton/meyer_laplacian.h"
#include "core/skeleton/sparse_cholesky.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

namespace trimlab {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point& start)
{
    const Clock::time_point now = Clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - start).count();
    start = now;
    return ms;
}

// Component id of every vertex, joined through the triangles that entered the Laplacian.
std::vector<std::uint32_t> laplacianComponents(std::size_t vertexCount, const std::vector<LaplacianEdge>& edges)
{
    std::vector<std::uint32_t> parent(vertexCount);
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](std::uint32_t v) {
        while (parent[v] != v)
            v = parent[v] = parent[parent[v]];
        return v;
    };
    for (const LaplacianEdge& e : edges) {
        const std::uint32_t a = find(e.i), b = find(e.j);
        if (a != b)
            parent[std::max(a, b)] = std::min(a, b);
    }
    for (std::uint32_t v = 0; v < vertexCount; ++v)
        parent[v] = find(v);
    return parent;
}

// True for the vertices whose component has no heat source (Σ A_j·H_jj = 0 over it).
std::vector<std::uint8_t> pinnedVertices(const MeyerLaplacian& laplacian, const BoneHeatTerms& terms)
{
    const std::size_t n = laplacian.area.size();
    const std::vector<std::uint32_t> component = laplacianComponents(n, laplacian.edges);
    std::vector<std::uint8_t> live(n, 0);
    for (std::size_t j = 0; j < n; ++j)
        if (laplacian.area[j] * terms.heat[j] > 0.0)
            live[component[j]] = 1;
    std::vector<std::uint8_t> pinned(n);
    for (std::size_t j = 0; j < n; ++j)
        pinned[j] = live[component[j]] ? 0 : 1;
    return pinned;
}

// The system (L + A·H) w = A·H·p as its lower triangle, with pinned rows w_j = p̃_j.
struct HeatSystem {
    SkeletonSparseMatrix lower;
    Eigen::MatrixXd rhs; // #V × B
};

HeatSystem heatSystem(const MeyerLaplacian& laplacian, const BoneHeatTerms& terms,
                      const std::vector<std::uint8_t>& pinned, std::size_t boneCount)
{
    const std::size_t n = laplacian.area.size();
    HeatSystem system;
    system.rhs = Eigen::MatrixXd::Zero(Eigen::Index(n), Eigen::Index(boneCount));
    std::vector<Eigen::Triplet<double, int>> entries;
    entries.reserve(n + laplacian.edges.size());
    for (std::size_t j = 0; j < n; ++j) {
        const std::span<const int> nearest = terms.nearest(j);
        if (pinned[j]) { // every nearest bone, visible or not, shares the weight
            entries.emplace_back(int(j), int(j), 1.0);
            for (const int b : nearest)
                system.rhs(Eigen::Index(j), b) = 1.0 / double(nearest.size());
            continue;
        }
        const double areaHeat = laplacian.area[j] * terms.heat[j];
        entries.emplace_back(int(j), int(j), laplacian.diagonal[j] + areaHeat);
        for (std::size_t e = 0; e < nearest.size(); ++e)
            if (terms.visible[terms.nearestOffsets[j] + e])
                system.rhs(Eigen::Index(j), nearest[e]) = areaHeat / double(terms.visibleCount(j));
    }
    for (const LaplacianEdge& e : laplacian.edges)
        if (!pinned[e.i]) // a live edge joins two vertices of one live component
            entries.emplace_back(int(e.j), int(e.i), -e.weight);
    system.lower.resize(Eigen::Index(n), Eigen::Index(n));
    system.lower.setFromTriplets(entries.begin(), entries.end());
    system.lower.makeCompressed();
    return system;
}

// Analyzes and factorizes with `backend`; nullptr and `error` set on failure.
std::unique_ptr<SparseCholesky> factorized(const SkeletonSparseMatrix& lower, SparseBackend backend,
                                           SparseOrdering ordering, std::string& error)
{
    SkeletonSparseMatrix full;
    if (ordering == SparseOrdering::Colamd)
        full = lower.selfadjointView<Eigen::Lower>();
    std::unique_ptr<SparseCholesky> solver =
        makeSparseCholesky(backend, ordering, ordering == SparseOrdering::Colamd ? &full : nullptr);
    if (!solver->analyze(lower, error) || !solver->factorize(lower, error))
        return nullptr;
    return solver;
}

// Solves for every bone, three right-hand sides at a time (the factorization interface
// takes #V×3 blocks); the result is bone-major.
std::vector<double> solveColumns(SparseCholesky& solver, const Eigen::MatrixXd& rhs, const TaskControl& control)
{
    const Eigen::Index n = rhs.rows(), bones = rhs.cols();
    std::vector<double> columns(std::size_t(n * bones));
    const Eigen::Index batches = (bones + 2) / 3;
    for (Eigen::Index batch = 0; batch < batches; ++batch) {
        control.throwIfCancelled();
        Eigen::MatrixX3d block = Eigen::MatrixX3d::Zero(n, 3);
        const Eigen::Index first = 3 * batch, count = std::min<Eigen::Index>(3, bones - first);
        block.leftCols(count) = rhs.middleCols(first, count);
        Eigen::MatrixX3d x;
        std::string error;
        if (!solver.solve(block, x, error))
            throw std::runtime_error("bone heat weights: " + error);
        for (Eigen::Index c = 0; c < count; ++c)
            for (Eigen::Index j = 0; j < n; ++j)
                columns[std::size_t((first + c) * n + j)] = x(j, c);
        control.report("weights", std::size_t(batch + 1), std::size_t(batches));
    }
    return columns;
}

// The four largest raw weights of vertex j, negatives clamped, renormalised; or the
// nearest-bone fallback when nothing positive is left. Returns true for the fallback.
// `candidates` is scratch space.
bool sparseVertexWeights(const std::vector<double>& columns, std::size_t n, std::size_t boneCount, std::size_t j,
                         std::span<const int> nearest, std::vector<std::pair<double, int>>& candidates,
                         std::array<int, kBoneInfluences>& bones, std::array<float, kBoneInfluences>& weights)
{
    candidates.resize(boneCount);
    for (std::size_t b = 0; b < boneCount; ++b)
        candidates[b] = {columns[b * n + j], int(b)};
    if (strongestInfluences(candidates, bones, weights))
        return false;
    const std::size_t count = std::min(kBoneInfluences, nearest.size());
    for (std::size_t k = 0; k < count; ++k) {
        bones[k] = nearest[k];
        weights[k] = float(1.0 / double(count));
    }
    return true;
}

} // namespace

bool strongestInfluences(std::vector<std::pair<double, int>>& candidates, std::array<int, kBoneInfluences>& bones,
                         std::array<float, kBoneInfluences>& weights)
{
    for (auto& [w, bone] : candidates)
        w = std::isfinite(w) ? std::max(w, 0.0) : 0.0;
    const std::size_t kept = std::min(kBoneInfluences, candidates.size());
    std::partial_sort(
        candidates.begin(), candidates.begin() + std::ptrdiff_t(kept), candidates.end(),
        [](const auto& a, const auto& b) { return a.first != b.first ? a.first > b.first : a.second < b.second; });
    double sum = 0.0;
    for (std::size_t k = 0; k < kept; ++k)
        sum += candidates[k].first;
    bones.fill(-1);
    weights.fill(0.0f);
    if (!(sum > 1e-12))
        return false;
    for (std::size_t k = 0, slot = 0; k < kept; ++k)
        if (candidates[k].first > 0.0) {
            bones[slot] = candidates[k].second;
            weights[slot++] = float(candidates[k].first / sum);
        }
    return true;
}

BoneHeatSolver::BoneHeatSolver(const TriangleMesh& mesh, const SkeletonRig& rig, const BoneHeatOptions& options,
                               const TaskControl& control)
    : m_boneCount(rig.bones.size())
{
    if (mesh.vertexCount() == 0)
        throw std::invalid_argument("bone heat: the mesh has no vertices");
    Clock::time_point clock = Clock::now();
    const std::vector<glm::dvec3> positions(mesh.positions.begin(), mesh.positions.end());
    const MeyerLaplacian laplacian = meyerLaplacian(positions, mesh.triangles);
    m_report.skippedTriangles = laplacian.skippedTriangles;
    m_report.laplacianMs = msSince(clock);
    m_terms = boneHeatTerms(mesh, rig, options.terms, control);
    m_report.hiddenVertices = m_terms.hiddenVertices;
    m_report.heatTermsMs = msSince(clock);
    const std::vector<std::uint8_t> pinned = pinnedVertices(laplacian, m_terms);
    m_report.pinnedVertices = std::size_t(std::count(pinned.begin(), pinned.end(), std::uint8_t(1)));
    const HeatSystem system = heatSystem(laplacian, m_terms, pinned, m_boneCount);
    control.throwIfCancelled();
    std::string error;
    std::unique_ptr<SparseCholesky> solver = factorized(system.lower, options.backend, options.ordering, error);
    if (!solver && options.backend != SparseBackend::EigenSimplicialLdlt) {
        m_report.note = error + " Fell back to Eigen's SimplicialLDLT.";
        solver = factorized(system.lower, SparseBackend::EigenSimplicialLdlt, SparseOrdering::Amd, error);
    }
    if (!solver)
        throw std::runtime_error("bone heat weights: the system could not be factorized: " + error);
    m_report.factorization = solver->description();
    m_report.factorizationMs = msSince(clock);
    m_columns = solveColumns(*solver, system.rhs, control);
    m_report.solveMs = msSince(clock);
    const std::size_t n = mesh.vertexCount();
    m_weights.bones.resize(n);
    m_weights.weights.resize(n);
    std::vector<std::pair<double, int>> candidates;
    for (std::size_t j = 0; j < n; ++j)
        m_report.fallbackVertices += sparseVertexWeights(m_columns, n, m_boneCount, j, m_terms.nearest(j), candidates,
                                                         m_weights.bones[j], m_weights.weights[j])
                                         ? 1
                                         : 0;
    m_report.sparsifyMs = msSince(clock);
}

std::vector<double> BoneHeatSolver::boneWeightColumn(int bone) const
{
    if (bone < 0 || std::size_t(bone) >= m_boneCount)
        throw std::out_of_range("bone heat: bone " + std::to_string(bone) + " of " + std::to_string(m_boneCount));
    const std::size_t n = vertexCount();
    const auto first = m_columns.begin() + std::ptrdiff_t(std::size_t(bone) * n);
    return std::vector<double>(first, first + std::ptrdiff_t(n));
}

BoneWeights boneHeatWeights(const TriangleMesh& mesh, const SkeletonRig& rig, const BoneHeatOptions& options,
                            const TaskControl& control)
{
    return BoneHeatSolver(mesh, rig, options, control).weights();
}

} // namespace trimlab
