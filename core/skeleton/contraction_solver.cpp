#include "core/skeleton/contraction_solver.h"

#include "core/skeleton/contraction_remeshing.h"
#include "core/skeleton/cotangent_laplacian.h"
#include "core/skeleton/normal_equations.h"
#include "core/skeleton/sparse_cholesky.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cstddef>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <utility>

namespace trimlab {

namespace {

double triangleArea(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
    return 0.5 * glm::length(glm::cross(b - a, c - a));
}

void checkOptions(const ContractionOptions& o)
{
    const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
    if (!positive(o.initialAttractionWeight) || !std::isfinite(o.initialContractionWeight) ||
        !(o.contractionGrowth >= 1.0) || !std::isfinite(o.contractionGrowth) || !positive(o.maxContractionWeight) ||
        !positive(o.maxAttractionWeight))
        throw std::invalid_argument("contraction weights must be finite and positive, with s_L >= 1");
    if (!(o.minAngleDegrees > 0.0 && o.minAngleDegrees < 60.0))
        throw std::invalid_argument("minAngleDegrees must lie in (0, 60)");
    if (!(o.minAreaRatio >= 0.0) || !(o.minAreaDecrease >= 0.0 && o.minAreaDecrease < 1.0))
        throw std::invalid_argument("minAreaRatio must be >= 0 and minAreaDecrease in [0, 1)");
    if (!std::isfinite(o.collapseFraction) || o.collapseFraction >= 1.0 || !std::isfinite(o.inputCollapseFraction) ||
        o.inputCollapseFraction >= 1.0)
        throw std::invalid_argument("collapseFraction and inputCollapseFraction must be finite and below 1");
    if (o.maxIterations < 1)
        throw std::invalid_argument("maxIterations must be at least 1");
    if (!std::isfinite(o.medialWeight) || o.medialWeight < 0.0)
        throw std::invalid_argument("medialWeight must be finite and >= 0");
}

double medianEdgeLength(const std::vector<glm::dvec3>& positions, const std::vector<glm::uvec3>& triangles)
{
    std::vector<double> lengths;
    lengths.reserve(triangles.size() * 3 / 2);
    for (const glm::uvec3& t : triangles)
        for (int k = 0; k < 3; ++k)
            if (t[k] < t[(k + 1) % 3])
                lengths.push_back(glm::length(positions[t[k]] - positions[t[(k + 1) % 3]]));
    if (lengths.empty())
        return 0.0;
    auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
    std::nth_element(lengths.begin(), middle, lengths.end());
    return *middle;
}

// Before the area has fallen by this fraction, W_L is still too small to move anything
// and area changes are rounding noise, so a rise does not mean the contraction diverged.
constexpr double kContractionUnderway = 0.99;

} // namespace

struct ContractionSolver::State {
    ContractionOptions options;
    // The current (remeshed) mesh; groupOf maps each input vertex to the vertex holding it.
    std::vector<glm::uvec3> triangles;
    std::vector<glm::dvec3> positions;
    std::vector<int> groupOf;
    double collapseLength = 0.0;
    std::size_t collapses = 0;
    std::unique_ptr<CotangentLaplacian> laplacian;
    std::unique_ptr<NormalEquations> normal;
    SkeletonSparseMatrix colamdSource; // A's pattern, only for SparseOrdering::Colamd
    std::unique_ptr<SparseCholesky> factor;
    SparseBackend backend;
    bool analyzed = false;

    double maxCotangent = 0.0;
    double contractionWeight = 0.0;
    std::vector<double> contractionWeights; // W_L as the diagonal matrix of eq. (2)
    std::vector<double> attractionWeights;  // W_H
    // Medial attraction (ContractionOptions::medialWeight): per input vertex its medial
    // point or none; per current vertex the mean of its group's, or none.
    std::vector<std::optional<glm::dvec3>> inputMedial;
    std::vector<std::optional<glm::dvec3>> medialTargets;
    std::vector<double> initialRingAreas; // A_i⁰
    double initialArea = 0.0;
    double area = 0.0;
    std::vector<double> laplacianMagnitude;
    // Per input vertex, what positions() and laplacianMagnitude() return.
    std::vector<glm::dvec3> inputPositions;
    std::vector<double> inputMagnitude;
    int iterations = 0, analyses = 0, factorizations = 0;
    bool finished = false;
    std::vector<std::string> warnings;

    State(const TriangleMesh& mesh, const ContractionOptions& o)
        : options(o),
          triangles(mesh.triangles),
          positions(mesh.positions.begin(), mesh.positions.end()),
          groupOf(mesh.positions.size()),
          backend(o.backend)
    {
        for (std::size_t v = 0; v < groupOf.size(); ++v)
            groupOf[v] = static_cast<int>(v);
        inputPositions = positions;
        inputMagnitude.assign(positions.size(), 0.0);
        const Bounds bounds = computeBounds(mesh);
        collapseLength = o.collapseFraction > 0.0 && bounds.valid()
                             ? o.collapseFraction * glm::length(bounds.max - bounds.min)
                             : 0.0;
        buildSystem();
    }

    // The Laplacian and normal-equation patterns of the current connectivity; a new
    // pattern needs a new symbolic analysis.
    void buildSystem()
    {
        laplacian = std::make_unique<CotangentLaplacian>(positions.size(), triangles);
        normal = std::make_unique<NormalEquations>(laplacian->matrix());
        analyzed = false;
    }

    // The medial target of each current vertex: the mean of the medial points of the input
    // vertices it holds (after remeshing a vertex holds several).
    void refreshMedial()
    {
        if (inputMedial.empty())
            return;
        std::vector<glm::dvec3> sum(positions.size(), glm::dvec3(0.0));
        std::vector<int> count(positions.size(), 0);
        for (std::size_t v = 0; v < groupOf.size(); ++v)
            if (inputMedial[v]) {
                const auto g = static_cast<std::size_t>(groupOf[v]);
                sum[g] += *inputMedial[v];
                ++count[g];
            }
        medialTargets.assign(positions.size(), std::nullopt);
        for (std::size_t g = 0; g < positions.size(); ++g)
            if (count[g] > 0)
                medialTargets[g] = sum[g] / double(count[g]);
    }

    void expandToInput()
    {
        for (std::size_t v = 0; v < groupOf.size(); ++v) {
            inputPositions[v] = positions[static_cast<std::size_t>(groupOf[v])];
            inputMagnitude[v] = laplacianMagnitude[static_cast<std::size_t>(groupOf[v])];
        }
    }

    // Collapses the edges that became shorter than collapseLength; merged vertices sum
    // their A_i⁰ (the area their rings had) and keep the larger W_H. Returns whether the
    // connectivity changed.
    bool remesh(double length)
    {
        if (length <= 0.0)
            return false;
        CollapsedMesh collapsed = collapseShortEdges(positions, triangles, length);
        if (collapsed.collapses == 0)
            return false;
        collapses += collapsed.collapses;
        const std::size_t n = collapsed.positions.size();
        std::vector<double> ringAreas0(n, 0.0), attraction(n, 0.0), magnitude(n, 0.0);
        for (std::size_t v = 0; v < positions.size(); ++v) {
            const auto to = static_cast<std::size_t>(collapsed.newIndex[v]);
            ringAreas0[to] += initialRingAreas[v];
            attraction[to] = std::max(attraction[to], attractionWeights[v]);
            magnitude[to] = std::max(magnitude[to], laplacianMagnitude[v]);
        }
        for (int& g : groupOf)
            g = collapsed.newIndex[static_cast<std::size_t>(g)];
        positions = std::move(collapsed.positions);
        triangles = std::move(collapsed.triangles);
        initialRingAreas = std::move(ringAreas0);
        attractionWeights = std::move(attraction);
        laplacianMagnitude = std::move(magnitude);
        contractionWeights.assign(n, contractionWeight);
        buildSystem();
        if (options.ordering == SparseOrdering::Colamd)
            colamdSource = normal->stackedPattern(laplacian->matrix());
        factor = makeSparseCholesky(backend, options.ordering,
                                    options.ordering == SparseOrdering::Colamd ? &colamdSource : nullptr);
        return true;
    }

    // A_i of `at` (the area of the triangles around each vertex); returns the total area.
    double ringAreas(const std::vector<glm::dvec3>& at, std::vector<double>& areas) const
    {
        areas.assign(at.size(), 0.0);
        double total = 0.0;
        for (const glm::uvec3& t : triangles) {
            const double a = triangleArea(at[t[0]], at[t[1]], at[t[2]]);
            total += a;
            for (int c = 0; c < 3; ++c)
                areas[t[c]] += a;
        }
        return total;
    }

    void makeFactor()
    {
        factor = makeSparseCholesky(backend, options.ordering,
                                    options.ordering == SparseOrdering::Colamd ? &colamdSource : nullptr);
        analyzed = false;
    }

    // One attempt with the current factorization; false + error on failure.
    bool trySolve(const Eigen::MatrixX3d& rhs, Eigen::MatrixX3d& x, std::string& error)
    {
        if (!analyzed) {
            ++analyses;
            if (!factor->analyze(normal->lower(), error))
                return false;
            analyzed = true;
        }
        ++factorizations;
        return factor->factorize(normal->lower(), error) && factor->solve(rhs, x, error) && x.allFinite();
    }

    Eigen::MatrixX3d solve(const Eigen::MatrixX3d& rhs)
    {
        Eigen::MatrixX3d x;
        std::string error;
        if (trySolve(rhs, x, error))
            return x;
        if (error.empty())
            error = factor->description() + " gave a non-finite solution.";
        if (backend != SparseBackend::Cholmod)
            throw std::runtime_error("Contraction failed in iteration " + std::to_string(iterations + 1) + ": " +
                                     error);
        warnings.push_back(error + " Falling back to Eigen SimplicialLDLT with " + orderingName(options.ordering) +
                           " ordering.");
        backend = SparseBackend::EigenSimplicialLdlt;
        makeFactor();
        error.clear();
        if (trySolve(rhs, x, error))
            return x;
        throw std::runtime_error("Contraction failed in iteration " + std::to_string(iterations + 1) + ": " +
                                 (error.empty() ? std::string("non-finite solution") : error));
    }

    // W_L ← s_L·W_L and W_H,i ← W_H⁰·√(A_i⁰/A_i), both capped (III.A steps 2–3).
    void updateWeights(const std::vector<double>& areas)
    {
        contractionWeight = std::min(contractionWeight * options.contractionGrowth, options.maxContractionWeight);
        std::fill(contractionWeights.begin(), contractionWeights.end(), contractionWeight);
        for (std::size_t i = 0; i < areas.size(); ++i) {
            // A collapsed ring (A_i = 0) gets the cap (√∞ = ∞ > cap); a ring that had no
            // area to begin with (degenerate input) keeps W_H⁰.
            const double a0 = initialRingAreas[i];
            attractionWeights[i] = a0 <= 0.0 ? options.initialAttractionWeight
                                             : std::min(options.maxAttractionWeight,
                                                        options.initialAttractionWeight * std::sqrt(a0 / areas[i]));
        }
    }

    // Solves eq. (2) for the next positions and ‖L·V'‖ per vertex.
    std::vector<glm::dvec3> contract(std::vector<double>& magnitude)
    {
        Eigen::MatrixX3d x;
        if (medialTargets.empty()) {
            normal->update(laplacian->matrix(), contractionWeights, attractionWeights);
            x = solve(NormalEquations::rightHandSide(positions, attractionWeights));
        } else {
            // W_H·(V' − V) and μ·W_H·(V' − M) folded into one row (ContractionOptions::medialWeight).
            const double mu2 = options.medialWeight * options.medialWeight;
            std::vector<double> weights(attractionWeights);
            std::vector<glm::dvec3> targets(positions);
            for (std::size_t i = 0; i < positions.size(); ++i)
                if (medialTargets[i]) {
                    weights[i] *= std::sqrt(1.0 + mu2);
                    targets[i] = (positions[i] + mu2 * *medialTargets[i]) / (1.0 + mu2);
                }
            normal->update(laplacian->matrix(), contractionWeights, weights);
            x = solve(NormalEquations::rightHandSide(targets, weights));
        }
        const Eigen::MatrixX3d lx = laplacian->matrix() * x;
        std::vector<glm::dvec3> next(positions.size());
        magnitude.resize(positions.size());
        for (std::size_t i = 0; i < positions.size(); ++i) {
            const auto r = static_cast<Eigen::Index>(i);
            next[i] = glm::dvec3(x(r, 0), x(r, 1), x(r, 2));
            magnitude[i] = lx.row(r).norm();
        }
        return next;
    }
};

ContractionSolver::ContractionSolver(const TriangleMesh& mesh, const ContractionOptions& options,
                                     std::span<const std::optional<glm::dvec3>> medial)
{
    if (mesh.triangles.empty())
        throw std::invalid_argument("contraction needs a mesh with triangles");
    checkOptions(options);
    if (!medial.empty() && medial.size() != mesh.vertexCount())
        throw std::invalid_argument("contraction: " + std::to_string(medial.size()) + " medial points for " +
                                    std::to_string(mesh.vertexCount()) + " vertices");
    m = std::make_unique<State>(mesh, options);
    State& s = *m;
    if (options.medialWeight > 0.0 && !medial.empty())
        s.inputMedial.assign(medial.begin(), medial.end());
    // Angles clamped to [θmin, 180° − θmin], i.e. |cot| ≤ cot θmin (cot 1° ≈ 57.3): the
    // cotangents stay finite as triangles collapse (paper III.A, detail 1).
    s.maxCotangent = 1.0 / std::tan(options.minAngleDegrees * glm::pi<double>() / 180.0);
    s.initialArea = s.ringAreas(s.positions, s.initialRingAreas);
    s.area = s.initialArea;
    s.attractionWeights.assign(s.positions.size(), options.initialAttractionWeight);
    s.laplacianMagnitude.assign(s.positions.size(), 0.0);
    // A dense mesh is first decimated to the sampling the skeleton needs (its short edges
    // collapsed); the smaller mesh is then the one contracted, from its own areas.
    const Bounds bounds = computeBounds(mesh);
    const double diagonal = bounds.valid() ? glm::length(bounds.max - bounds.min) : 0.0;
    const double inputCollapse = options.inputCollapseFraction * diagonal;
    if (medianEdgeLength(s.positions, s.triangles) < inputCollapse && s.remesh(inputCollapse)) {
        s.initialArea = s.ringAreas(s.positions, s.initialRingAreas);
        s.area = s.initialArea;
        std::fill(s.attractionWeights.begin(), s.attractionWeights.end(), options.initialAttractionWeight);
        s.expandToInput();
    }
    s.refreshMedial();
    // See ContractionOptions::initialContractionWeight for why 1 and not the paper's 10⁻³·√Ā.
    s.contractionWeight = options.initialContractionWeight > 0.0 ? options.initialContractionWeight : 1.0;

    s.contractionWeight = std::min(s.contractionWeight, options.maxContractionWeight);
    s.contractionWeights.assign(s.positions.size(), s.contractionWeight);
    s.laplacian->update(s.positions, s.maxCotangent);
    if (options.ordering == SparseOrdering::Colamd)
        s.colamdSource = s.normal->stackedPattern(s.laplacian->matrix());
    s.makeFactor();
}

ContractionSolver::~ContractionSolver() = default;

bool ContractionSolver::iterate()
{
    State& s = *m;
    if (s.finished)
        return false;
    std::vector<double> magnitude;
    std::vector<glm::dvec3> next = s.contract(magnitude);
    std::vector<double> areas;
    const double nextArea = s.ringAreas(next, areas);
    const double previousArea = s.area;
    // The area rose although the contraction was underway: the iteration diverged (with
    // W_L large, near-degenerate triangles with negative cotangent weights let L·V' ≈ 0
    // far from the surface). Keep the previous positions and stop.
    if (nextArea > previousArea && previousArea < kContractionUnderway * s.initialArea) {
        s.finished = true;
        s.warnings.push_back("Contraction stopped after iteration " + std::to_string(s.iterations) + ": iteration " +
                             std::to_string(s.iterations + 1) + " increased the surface area and was discarded.");
        return true;
    }
    const bool contractionCapped = s.contractionWeight >= s.options.maxContractionWeight;
    s.positions = std::move(next);
    s.laplacianMagnitude = std::move(magnitude);
    s.area = nextArea;
    ++s.iterations;
    s.updateWeights(areas);
    if (s.remesh(s.collapseLength))
        s.refreshMedial();
    s.area = s.ringAreas(s.positions, areas);
    s.laplacian->update(s.positions, s.maxCotangent);
    s.expandToInput();

    const double ratio = s.initialArea > 0.0 ? s.area / s.initialArea : 0.0;
    const bool stalled = contractionCapped && previousArea - s.area < s.options.minAreaDecrease * previousArea;
    s.finished = s.iterations >= s.options.maxIterations || ratio < s.options.minAreaRatio || stalled;
    return true;
}

void ContractionSolver::run(const TaskControl& control)
{
    const auto total = static_cast<std::size_t>(m->options.maxIterations);
    control.report("contraction", 0, total);
    while (!finished()) {
        control.throwIfCancelled();
        iterate();
        control.report("contraction", static_cast<std::size_t>(m->iterations), total);
    }
}

bool ContractionSolver::finished() const
{
    return m->finished;
}
const std::vector<glm::dvec3>& ContractionSolver::positions() const
{
    return m->inputPositions;
}
const std::vector<double>& ContractionSolver::laplacianMagnitude() const
{
    return m->inputMagnitude;
}
std::size_t ContractionSolver::vertexCount() const
{
    return m->positions.size();
}
std::size_t ContractionSolver::collapses() const
{
    return m->collapses;
}
int ContractionSolver::iterations() const
{
    return m->iterations;
}
int ContractionSolver::symbolicAnalyses() const
{
    return m->analyses;
}
int ContractionSolver::numericFactorizations() const
{
    return m->factorizations;
}
double ContractionSolver::areaRatio() const
{
    return m->initialArea > 0.0 ? m->area / m->initialArea : 0.0;
}
double ContractionSolver::contractionWeight() const
{
    return m->contractionWeight;
}
std::string ContractionSolver::solverDescription() const
{
    return m->factor->description();
}
const std::vector<std::string>& ContractionSolver::warnings() const
{
    return m->warnings;
}

} // namespace trimlab
