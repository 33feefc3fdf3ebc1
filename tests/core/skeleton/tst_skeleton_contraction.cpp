// Geometry contraction and simplification (core/skeleton/contraction_solver.h,
// skeleton_simplification.h; Berenguer & Moreno III.A–B) on a generated capsule, whose
// curve skeleton is known: the segment of its axis. Expected values come from the shape,
// not from the code under test.
#include "core/scene/shape_generators.h"
#include "core/skeleton/contraction_options.h"
#include "core/skeleton/contraction_remeshing.h"
#include "core/skeleton/contraction_solver.h"
#include "core/skeleton/cotangent_laplacian.h"
#include "core/skeleton/medial_targets.h"
#include "core/skeleton/normal_equations.h"
#include "core/skeleton/point_in_mesh.h"
#include "core/skeleton/shrinking_balls.h"
#include "core/skeleton/skeleton_refinement.h"
#include "core/skeleton/skeleton_simplification.h"
#include "core/skeleton/sparse_cholesky.h"

#include "skeleton_shapes.h"

#include <QtTest>

#include <glm/geometric.hpp>

#include <dlfcn.h>

#include <cmath>
#include <map>
#include <numeric>
#include <stop_token>
#include <thread>

using namespace trimlab;
using namespace trimlab::test;

namespace {

constexpr double kRadius = 0.5, kHalfLength = 1.5;

TriangleMesh capsule()
{
    return axisCapsule(kRadius, kHalfLength, 8, 24, 32);
}

double axisDistance(const glm::dvec3& p)
{
    return std::hypot(p.x, p.z);
}

// Contracted positions after exactly `iterations` solves with W_L⁰ = 1 (contracting from
// the first iteration), for comparing factorizations.
std::vector<glm::dvec3> contractWith(SparseBackend backend, SparseOrdering ordering, int iterations,
                                     std::string* description = nullptr)
{
    ContractionOptions options;
    options.backend = backend;
    options.ordering = ordering;
    options.initialContractionWeight = 1.0;
    options.maxIterations = iterations;
    // Fixed connectivity: remeshing would let a rounding difference decide whether an
    // edge at the collapse length collapses, which is not what this compares.
    options.collapseFraction = 0.0;
    ContractionSolver solver(capsule(), options);
    solver.run();
    if (description)
        *description = solver.solverDescription();
    return solver.positions();
}

double maxDifference(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b)
{
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        worst = std::max(worst, glm::length(a[i] - b[i]));
    return worst;
}

} // namespace

class TestSkeletonContraction : public QObject {
    Q_OBJECT

private slots:
    void clampedCotangentStaysFinite()
    {
        const double maxCot = 1.0 / std::tan(M_PI / 180.0); // the default clamp: 1°
        const glm::dvec3 o(0.0), x(1.0, 0.0, 0.0);
        QCOMPARE(clampedCotangent(o, x, glm::dvec3(0.5, std::sqrt(3.0) / 2.0, 0.0), maxCot) * std::sqrt(3.0), 1.0);
        QCOMPARE(clampedCotangent(o, x, glm::dvec3(1.0, 1e-9, 0.0), maxCot), maxCot);  // 1e-9 rad < 1°
        QCOMPARE(clampedCotangent(o, x, glm::dvec3(2.0, 0.0, 0.0), maxCot), maxCot);   // collinear, 0°
        QCOMPARE(clampedCotangent(o, x, glm::dvec3(-1.0, 0.0, 0.0), maxCot), -maxCot); // collinear, 180°
        QCOMPARE(clampedCotangent(o, o, x, maxCot), maxCot);                           // no angle at all
    }

    void capsuleContractsToItsAxis_data()
    {
        QTest::addColumn<double>("collapseFraction");
        QTest::newRow("remeshing") << 0.002; // the option contraction_options.h keeps for comparisons
        QTest::newRow("fixed connectivity") << 0.0;
    }

    void capsuleContractsToItsAxis()
    {
        QFETCH(double, collapseFraction);
        const TriangleMesh mesh = capsule();
        ContractionOptions options;
        options.collapseFraction = collapseFraction;
        ContractionSolver solver(mesh, options);
        solver.run();
        const std::vector<glm::dvec3>& p = solver.positions();
        QCOMPARE(p.size(), mesh.vertexCount());
        double sum = 0.0;
        for (const glm::dvec3& q : p) {
            QVERIFY(std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z));
            sum += axisDistance(q);
            QVERIFY(std::abs(q.y) <= kHalfLength + kRadius); // contraction never stretches the axis
        }
        const double mean = sum / static_cast<double>(p.size());
        qInfo("%d iterations, area ratio %.3g, mean distance to the axis %.3g·r; %s", solver.iterations(),
              solver.areaRatio(), mean / kRadius, solver.solverDescription().c_str());
        QVERIFY2(mean < 0.01 * kRadius, qPrintable(QString("mean distance %1").arg(mean)));
        QVERIFY(solver.iterations() >= 3);
        if (collapseFraction > 0.0) {
            // The contracted rings collapse: far fewer vertices, one new analysis per
            // iteration that changed the connectivity (at most one per solve).
            qInfo("remeshed to %zu of %zu vertices by %zu collapses, %d symbolic analyses", solver.vertexCount(),
                  mesh.vertexCount(), solver.collapses(), solver.symbolicAnalyses());
            QVERIFY(solver.vertexCount() < mesh.vertexCount() / 4);
            QCOMPARE(solver.vertexCount() + solver.collapses(), mesh.vertexCount());
            QVERIFY(solver.symbolicAnalyses() >= 2);
            QVERIFY(solver.symbolicAnalyses() <= solver.iterations() + 1);
        } else {
            // The pattern never changes: one symbolic analysis, one numeric factorization per solve.
            QCOMPARE(solver.vertexCount(), mesh.vertexCount());
            QCOMPARE(solver.symbolicAnalyses(), 1);
        }
        QVERIFY(solver.numericFactorizations() >= solver.iterations());
        QVERIFY(solver.numericFactorizations() <= solver.iterations() + 1); // + a discarded divergent solve
        QCOMPARE(solver.laplacianMagnitude().size(), mesh.vertexCount());
        for (double m : solver.laplacianMagnitude())
            QVERIFY(std::isfinite(m) && m >= 0.0);
    }

    // The medial points (medial_targets.h): on the tube each vertex keeps its chord
    // midpoint, which lies on the axis; at the caps' apexes the chord runs along the axis
    // (half a capsule long) and is dropped, so the medial attraction cannot pull the tips
    // back along the limb. With the attraction on, the contraction still reaches the axis
    // and the contracted axis is no shorter than without it.
    void medialTargetsSkipTheCapsOfLimbs()
    {
        const TriangleMesh mesh = capsule();
        const PointInMesh solid(mesh);
        const std::vector<std::optional<glm::dvec3>> midpoints = inwardChordMidpoints(mesh, solid);
        const std::vector<std::optional<glm::dvec3>> targets = medialTargets(mesh, midpoints);
        QCOMPARE(targets.size(), mesh.vertexCount());
        int side = 0, sideKept = 0, apex = 0, apexKept = 0;
        for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
            const double y = std::abs(double(mesh.positions[v].y));
            if (y < kHalfLength - 0.1) {
                ++side;
                if (targets[v]) {
                    ++sideKept;
                    const double off = axisDistance(*targets[v]);
                    QVERIFY2(off < 0.05 * kRadius,
                             qPrintable(QString("vertex %1: target %2 off the axis").arg(v).arg(off)));
                }
            } else if (y > kHalfLength + 0.9 * kRadius) {
                ++apex;
                apexKept += targets[v] ? 1 : 0;
            }
        }
        qInfo("tube: %d of %d vertices keep a medial point; cap apexes: %d of %d", sideKept, side, apexKept, apex);
        QVERIFY(side > 100 && apex > 4);
        QCOMPARE(sideKept, side);
        QCOMPARE(apexKept, 0);

        ContractionOptions options;
        options.medialWeight = 0.0;
        ContractionSolver plain(mesh, options);
        plain.run();
        options.medialWeight = 0.5;
        ContractionSolver medial(mesh, options, targets);
        medial.run();
        const auto extent = [](const std::vector<glm::dvec3>& p) {
            double reach = 0.0, axis = 0.0;
            for (const glm::dvec3& q : p) {
                reach = std::max(reach, std::abs(q.y));
                axis += axisDistance(q);
            }
            return std::pair(reach, axis / double(p.size()));
        };
        const auto [plainReach, plainAxis] = extent(plain.positions());
        const auto [medialReach, medialAxis] = extent(medial.positions());
        qInfo("contracted half-length: %.3f without the medial attraction, %.3f with it (mean distance to the axis "
              "%.3g·r, %.3g·r)",
              plainReach, medialReach, plainAxis / kRadius, medialAxis / kRadius);
        QVERIFY(medialAxis < 0.01 * kRadius);
        QVERIFY(medialReach >= plainReach - 1e-6);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 ContractionSolver(mesh, options, std::span(targets).first(targets.size() - 1)));
    }

    // On the capsule every vertex's medial ball is known: on the tube, radius r centred on
    // the axis; at the poles of the caps, the cap's hemisphere, centred where the cap
    // meets the tube. The chord from a pole runs along the whole axis to the other pole
    // (its midpoint is the capsule's centre, half a capsule away from the cap's centre);
    // the shrinking ball starts there and must end at the cap. With the balls as medial
    // points the contraction still reaches the axis, and the caps' centres.
    void shrinkingBallsSitOnTheAxisAndAtTheCapsCentres()
    {
        const TriangleMesh mesh = capsule();
        const PointInMesh solid(mesh);
        const std::vector<std::optional<glm::dvec3>> midpoints = inwardChordMidpoints(mesh, solid);
        const std::vector<std::optional<glm::dvec3>> centres = shrinkingBallCentres(mesh, midpoints, solid);
        QCOMPARE(centres.size(), mesh.vertexCount());
        int side = 0, apex = 0;
        for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
            const glm::dvec3 p(mesh.positions[v]);
            const double y = std::abs(p.y);
            const bool onSide = y < kHalfLength - 0.1;
            const bool atApex = y > kHalfLength + 0.9 * kRadius;
            if (!onSide && !atApex)
                continue;
            QVERIFY2(centres[v], qPrintable(QString("vertex %1 has no medial ball").arg(v)));
            const glm::dvec3 c = *centres[v];
            const double radius = glm::length(c - p);
            QVERIFY2(axisDistance(c) < 0.05 * kRadius && std::abs(radius - kRadius) < 0.05 * kRadius,
                     qPrintable(QString("vertex %1 at y %2: ball centre %3 off the axis, radius %4·r")
                                    .arg(v)
                                    .arg(p.y)
                                    .arg(axisDistance(c))
                                    .arg(radius / kRadius)));
            if (atApex) {
                ++apex;
                QVERIFY2(std::abs(std::abs(c.y) - kHalfLength) < 0.1 * kRadius,
                         qPrintable(QString("pole %1: ball centre at y %2, the cap's centre is at %3")
                                        .arg(v)
                                        .arg(c.y)
                                        .arg(kHalfLength)));
                if (axisDistance(p) < 1e-6) // the pole itself: its chord's midpoint is mid-capsule
                    QVERIFY(std::abs(midpoints[v]->y) < 0.1 * kRadius);
            } else {
                ++side;
            }
        }
        QVERIFY(side > 100 && apex > 4);

        ContractionOptions options;
        ContractionSolver plain(mesh, options);
        plain.run();
        options.medialWeight = 0.5;
        options.medialPoints = MedialPoints::ShrinkingBalls;
        ContractionSolver medial(mesh, options, centres);
        medial.run();
        double plainReach = 0.0, medialReach = 0.0, medialAxis = 0.0;
        for (const glm::dvec3& q : plain.positions())
            plainReach = std::max(plainReach, std::abs(q.y));
        for (const glm::dvec3& q : medial.positions()) {
            medialReach = std::max(medialReach, std::abs(q.y));
            medialAxis = std::max(medialAxis, axisDistance(q));
        }
        qInfo("contracted half-length: %.3f without the medial attraction, %.3f with the balls' centres "
              "(farthest from the axis %.3g·r)",
              plainReach, medialReach, medialAxis / kRadius);
        QVERIFY(medialAxis < 0.01 * kRadius);
        // The capsule's medial axis ends at the caps' centres, where the poles' balls pull
        // them: the contraction must reach that far (it stops short of the plain
        // contraction's reach; the leaf extension takes a leaf on to its tip).
        QVERIFY(medialReach >= kHalfLength);
        QVERIFY_THROWS_EXCEPTION(
            std::invalid_argument,
            shrinkingBallCentres(mesh, std::vector(midpoints.begin() + 1, midpoints.end()), solid));
    }

    void orderingsAndBackendsAgree()
    {
        // 8 iterations (W_L from 1 to 128) take the capsule from its surface to within
        // ~1e-3·r of its axis. The orderings only change the rounding: a solve's forward
        // error is about κ(AᵀA)·ε, with κ ≈ (W_L·‖L‖/W_H)² ≤ (128·~500)² ≈ 4e9 in the last
        // iteration (clamped cotangents reach 57), i.e. ~5e-7 relative — what is measured
        // (2e-7 to 5e-7·r). 1e-5·r leaves room for the few iterations compounding it; an
        // ordering applied wrongly (a permutation not undone) would be off by ~r.
        std::string description;
        const std::vector<glm::dvec3> reference =
            contractWith(SparseBackend::Cholmod, SparseOrdering::Metis, 8, &description);
        if (cholmodHasMetis())
            QVERIFY2(description.find("CHOLMOD") != std::string::npos && description.find("METIS") != std::string::npos,
                     description.c_str());
        else // the documented fallback: Eigen's SimplicialLDLT with Eigen's METIS ordering
            QVERIFY2(description.find("SimplicialLDLT") != std::string::npos, description.c_str());
        const struct {
            SparseBackend backend;
            SparseOrdering ordering;
            const char* named;
        } variants[] = {{SparseBackend::Cholmod, SparseOrdering::Amd, "AMD"},
                        {SparseBackend::Cholmod, SparseOrdering::Colamd, "COLAMD"},
                        {SparseBackend::EigenSimplicialLdlt, SparseOrdering::Amd, "AMD"},
                        {SparseBackend::EigenSimplicialLdlt, SparseOrdering::Colamd, "COLAMD"},
                        {SparseBackend::EigenSimplicialLdlt, SparseOrdering::Metis, "METIS"}};
        for (const auto& v : variants) {
            const std::vector<glm::dvec3> other = contractWith(v.backend, v.ordering, 8, &description);
            const double difference = maxDifference(reference, other);
            qInfo("%-60s max difference %.3g·r", description.c_str(), difference / kRadius);
            QVERIFY2(description.find(v.named) != std::string::npos, description.c_str());
            QVERIFY2(difference < 1e-5 * kRadius, qPrintable(QString::fromStdString(description)));
        }
    }

    // A contraction puts OpenBLAS on one thread (sparse_cholesky.cpp: its spinning threads
    // stalled the contraction 10-25x on a busy machine; measured by hand, not here). The
    // setting is process-wide, so the test first asks for two threads itself.
    void contractionRunsBlasOnOneThread()
    {
        using SetNumThreads = void (*)(int);
        using GetNumThreads = int (*)();
        const auto set = reinterpret_cast<SetNumThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
        const auto get = reinterpret_cast<GetNumThreads>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
        if (!set || !get)
            QSKIP("the BLAS here is not OpenBLAS: no threads to set");
        set(2);
        if (get() != 2)
            QSKIP("OpenBLAS runs one thread whatever is asked (a single-threaded build)");
        ContractionOptions options;
        options.backend = SparseBackend::Cholmod;
        options.maxIterations = 1;
        ContractionSolver solver(capsule(), options);
        solver.run();
        QCOMPARE(get(), 1);
    }

    // The remeshing's collapses keep a closed 2-manifold of the same genus (the link
    // condition), record where every vertex went, and put the kept vertex at the midpoint.
    // CHOLMOD's OpenMP teams are dynamic in the thread that runs a contraction, so they fit
    // the idle cores instead of oversubscribing a small machine (sparse_cholesky.cpp; the
    // time it saves is measured by bench_skeleton_cgal, not here). The setting is per
    // thread, so the contraction runs on a thread of its own, as the panel runs it.
    void cholmodRunsWithDynamicOpenMpTeams()
    {
        using GetDynamic = int (*)();
        const auto getDynamic = reinterpret_cast<GetDynamic>(dlsym(RTLD_DEFAULT, "omp_get_dynamic"));
        if (!getDynamic)
            QSKIP("this CHOLMOD brought no OpenMP runtime: nothing to make dynamic");
        int before = -1, after = -1;
        std::thread worker([&] {
            before = getDynamic();
            ContractionOptions options;
            options.backend = SparseBackend::Cholmod;
            options.maxIterations = 1;
            ContractionSolver solver(capsule(), options);
            solver.run();
            after = getDynamic();
        });
        worker.join();
        if (before == 1)
            QSKIP("OMP_DYNAMIC is set in the environment: teams were dynamic before the contraction");
        QCOMPARE(before, 0);
        QCOMPARE(after, 1);
    }

    void shortEdgesCollapseKeepingTheTopology()
    {
        const TriangleMesh torus = makeTorus({0, 0, 0}, 1.0, 0.3, 48, 16);
        std::vector<glm::dvec3> positions(torus.positions.begin(), torus.positions.end());
        // Squeeze the tube to a thin ring so its sections' edges become short, as contraction does.
        for (glm::dvec3& p : positions) {
            const double ring = std::hypot(p.x, p.z);
            const glm::dvec3 core(p.x / ring, 0.0, p.z / ring);
            p = core + 0.01 * (p - core);
        }
        const CollapsedMesh collapsed = collapseShortEdges(positions, torus.triangles, 0.02);
        qInfo("%zu collapses: %zu of %zu vertices, %zu triangles", collapsed.collapses, collapsed.positions.size(),
              positions.size(), collapsed.triangles.size());
        QVERIFY(collapsed.collapses > positions.size() / 2);
        QCOMPARE(collapsed.positions.size() + collapsed.collapses, positions.size());
        // Every edge in exactly two triangles, once each way; Euler characteristic 0.
        std::map<std::pair<unsigned, unsigned>, int> directed;
        for (const glm::uvec3& t : collapsed.triangles) {
            QVERIFY(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
            for (int k = 0; k < 3; ++k)
                ++directed[{t[k], t[(k + 1) % 3]}];
        }
        for (const auto& [edge, count] : directed) {
            QCOMPARE(count, 1);
            QVERIFY(directed.count({edge.second, edge.first}) == 1);
        }
        const long long euler = static_cast<long long>(collapsed.positions.size()) -
                                static_cast<long long>(directed.size() / 2) +
                                static_cast<long long>(collapsed.triangles.size());
        QCOMPARE(euler, 0LL);
        // Every input vertex maps to a survivor near it (within the collapse chain's reach).
        QCOMPARE(collapsed.newIndex.size(), positions.size());
        for (std::size_t v = 0; v < positions.size(); ++v) {
            const int to = collapsed.newIndex[v];
            QVERIFY(to >= 0 && to < int(collapsed.positions.size()));
            QVERIFY(glm::length(collapsed.positions[std::size_t(to)] - positions[v]) < 0.2);
        }
        // Nothing shorter than the threshold: nothing changes.
        const CollapsedMesh none = collapseShortEdges(positions, torus.triangles, 1e-6);
        QCOMPARE(none.collapses, std::size_t(0));
        QCOMPARE(none.triangles, torus.triangles);
    }

    void stopRequestCancelsContraction()
    {
        std::stop_source stop;
        int reports = 0;
        TaskControl control;
        control.stop = stop.get_token();
        control.progress = [&](const TaskProgress& p) {
            QCOMPARE(QString::fromUtf8(p.stage.data(), qsizetype(p.stage.size())), QString("contraction"));
            ++reports;
            if (p.done >= 1)
                stop.request_stop();
        };
        ContractionSolver solver(capsule(), ContractionOptions{});
        QVERIFY_THROWS_EXCEPTION(OperationCancelled, solver.run(control));
        QCOMPARE(solver.iterations(), 1); // stopped before the second solve
        QCOMPARE(reports, 2);             // the start and the first iteration
    }

    void contractedCapsuleSimplifiesToATreeOnTheAxis()
    {
        const TriangleMesh mesh = capsule();
        ContractionSolver solver(mesh, ContractionOptions{});
        solver.run();
        const double diagonal =
            std::sqrt(2.0 * std::pow(2.0 * kRadius, 2) + std::pow(2.0 * (kHalfLength + kRadius), 2));
        const CurveSkeleton curve = simplifyContractedMesh(solver.positions(), mesh.triangles, 1e-3 * diagonal, {});
        // A tree (genus 0): connected, N − 1 edges, no triangles left to hold a cycle.
        QVERIFY(curve.nodes.size() >= 3);
        QCOMPARE(curve.edges.size(), curve.nodes.size() - 1);
        std::vector<int> component(curve.nodes.size());
        std::iota(component.begin(), component.end(), 0);
        const auto root = [&](int k) {
            while (component[static_cast<std::size_t>(k)] != k)
                k = component[static_cast<std::size_t>(k)];
            return k;
        };
        for (const auto& e : curve.edges) {
            QVERIFY(e[0] < e[1]);
            component[static_cast<std::size_t>(root(e[0]))] = root(e[1]);
        }
        for (std::size_t k = 0; k < curve.nodes.size(); ++k)
            QCOMPARE(root(int(k)), root(0));
        // On the axis, reaching both contracted ends.
        double low = 0.0, high = 0.0;
        for (const glm::dvec3& node : curve.nodes) {
            QVERIFY(axisDistance(node) < 0.01 * kRadius);
            low = std::min(low, node.y);
            high = std::max(high, node.y);
        }
        double contractedLow = 0.0, contractedHigh = 0.0;
        for (const glm::dvec3& p : solver.positions()) {
            contractedLow = std::min(contractedLow, p.y);
            contractedHigh = std::max(contractedHigh, p.y);
        }
        QCOMPARE(low, contractedLow); // the end vertices survive: skeleton edges never collapse
        QCOMPARE(high, contractedHigh);
        QVERIFY(high - low > 2.0 * kHalfLength);
        // Every vertex belongs to a node.
        QCOMPARE(curve.vertexNode.size(), mesh.vertexCount());
        for (int k : curve.vertexNode)
            QVERIFY(k >= 0 && k < int(curve.nodes.size()));
    }

    // The normal equations against the dense product on a tetrahedron: the lower triangle
    // of L·diag(W_L²)·L + diag(W_H²), the right-hand side W_H²·V and A = [L; I]'s pattern.
    void normalEquationsMatchTheDenseProduct()
    {
        const std::vector<glm::dvec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.3, 1}};
        const std::vector<glm::uvec3> faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
        CotangentLaplacian laplacian(positions.size(), faces);
        laplacian.update(positions, 1.0 / std::tan(M_PI / 180.0));
        const std::vector<double> contraction = {1.0, 2.0, 0.5, 3.0}, attraction = {1.5, 1.0, 2.0, 0.25};

        NormalEquations equations(laplacian.matrix());
        equations.update(laplacian.matrix(), contraction, attraction);
        const Eigen::MatrixXd l(laplacian.matrix());
        Eigen::VectorXd wl2(4), wh2(4);
        for (int i = 0; i < 4; ++i) {
            wl2[i] = contraction[std::size_t(i)] * contraction[std::size_t(i)];
            wh2[i] = attraction[std::size_t(i)] * attraction[std::size_t(i)];
        }
        const Eigen::MatrixXd expected = l * wl2.asDiagonal() * l + Eigen::MatrixXd(wh2.asDiagonal());
        const Eigen::MatrixXd lower(equations.lower());
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                QVERIFY2(std::abs(lower(r, c) - (r >= c ? expected(r, c) : 0.0)) < 1e-12,
                         qPrintable(QString("(%1, %2)").arg(r).arg(c)));

        const Eigen::MatrixX3d rhs = NormalEquations::rightHandSide(positions, attraction);
        for (int i = 0; i < 4; ++i)
            for (int k = 0; k < 3; ++k)
                QCOMPARE(rhs(i, k), wh2[i] * positions[std::size_t(i)][k]);

        const Eigen::MatrixXd stacked(equations.stackedPattern(laplacian.matrix()));
        QCOMPARE(stacked.rows(), Eigen::Index(8));
        QCOMPARE(stacked.cols(), Eigen::Index(4));
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) {
                QCOMPARE(stacked(r, c), laplacian.matrix().coeff(r, c) != 0.0 ? 1.0 : 0.0);
                QCOMPARE(stacked(4 + r, c), r == c ? 1.0 : 0.0);
            }
    }

    // ContractionOptions::initialContractionWeight ≤ 0 means 1: the same solves, bit for bit.
    void nonPositiveInitialContractionWeightMeansOne()
    {
        const auto contractFrom = [](double weight) {
            ContractionOptions options;
            options.initialContractionWeight = weight;
            options.maxIterations = 3;
            ContractionSolver solver(capsule(), options);
            solver.run();
            return solver.positions();
        };
        const std::vector<glm::dvec3> one = contractFrom(1.0);
        QCOMPARE(contractFrom(0.0), one);
        QCOMPARE(contractFrom(-5.0), one);
        QVERIFY(maxDifference(contractFrom(4.0), one) > 1e-6 * kRadius);
    }
};

QTEST_APPLESS_MAIN(TestSkeletonContraction)
#include "tst_skeleton_contraction.moc"
