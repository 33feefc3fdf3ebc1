// Skeleton extraction timings (not a test: it never fails on speed and is not registered
// with CTest). Run by hand, e.g.
//   build/tests/core/skeleton/bench_skeleton ../shared/data/static/odedstein-cat-low-resolution.obj.gz
//   build/tests/core/skeleton/bench_skeleton --orderings --subdivide 1 ../shared/data/static/odedstein-armadillo.obj.gz
// For each mesh (optionally Loop-subdivided N times, to reach the paper's sizes) it prints
// the stage times of extractSkeleton (paper Table III), the contraction's iterations,
// symbolic analyses and numeric factorizations, the node counts, and with --orderings the
// contraction time under each ordering and backend (paper Table I).
#include "core/mesh/loop_subdivision.h"
#include "core/mesh/mesh_io.h"
#include "core/skeleton/contraction_solver.h"
#include "core/skeleton/skeleton_extraction.h"

#include <QCoreApplication>
#include <QCommandLineParser>
#include <QDateTime>
#include <QElapsedTimer>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <thread>

using namespace trimlab;

namespace {

void printExtraction(const TriangleMesh& mesh, const SkeletonOptions& options)
{
    const SkeletonExtraction r = extractSkeleton(mesh, options);
    const SkeletonStageTimes& t = r.times;
    std::vector<int> degree(r.rig.joints.size(), 0);
    for (const Bone& b : r.rig.bones) {
        ++degree[static_cast<std::size_t>(b.head)];
        ++degree[static_cast<std::size_t>(b.tail)];
    }
    const auto leaves = std::count(degree.begin(), degree.end(), 1);
    const auto junctions = std::count_if(degree.begin(), degree.end(), [](int d) { return d >= 3; });
    std::printf("  stages (ms): contraction %.1f  simplification %.1f  refinement %.1f  selection %.1f  total %.1f\n",
                t.contractionMs, t.simplificationMs, t.refinementMs, t.selectionMs,
                t.contractionMs + t.simplificationMs + t.refinementMs + t.selectionMs);
    std::printf("  contraction: %d iterations, %d symbolic analyses, %d numeric factorizations; %s\n",
                r.contractionIterations, r.symbolicAnalyses, r.numericFactorizations, r.solver.c_str());
    for (const std::string& w : r.warnings)
        std::printf("  note: %s\n", w.c_str());
    std::printf("  curve skeleton: %zu nodes, %zu edges; rig: %zu joints (%ld leaves, %ld junctions), root %d\n",
                r.curve.nodes.size(), r.curve.edges.size(), r.rig.joints.size(), static_cast<long>(leaves),
                static_cast<long>(junctions), r.rig.root);
}

void printOrderings(const TriangleMesh& mesh, const ContractionOptions& base)
{
    const struct {
        SparseBackend backend;
        SparseOrdering ordering;
    } variants[] = {{SparseBackend::Cholmod, SparseOrdering::Amd},
                    {SparseBackend::Cholmod, SparseOrdering::Colamd},
                    {SparseBackend::Cholmod, SparseOrdering::Metis},
                    {SparseBackend::EigenSimplicialLdlt, SparseOrdering::Metis}};
    for (const auto& v : variants) {
        ContractionOptions options = base;
        options.backend = v.backend;
        options.ordering = v.ordering;
        QElapsedTimer timer;
        timer.start();
        ContractionSolver solver(mesh, options);
        solver.run();
        const double ms = double(timer.nsecsElapsed()) / 1e6;
        std::printf("  %-62s %8.1f ms  (%d factorizations, %.1f ms each incl. assembly)\n",
                    solver.solverDescription().c_str(), ms, solver.numericFactorizations(),
                    ms / std::max(1, solver.numericFactorizations()));
    }
}

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    QCommandLineParser parser;
    parser.setApplicationDescription("Times skeleton extraction by mesh contraction (stages A-D).");
    parser.addHelpOption();
    parser.addOption({"subdivide", "Loop-subdivide each mesh N times first.", "N", "0"});
    parser.addOption({"orderings", "Also time the contraction with AMD, COLAMD, METIS and Eigen's LDLT."});
    parser.addOption({"target", "Joints after selection.", "N", "30"});
    parser.addPositionalArgument("meshes", "Mesh files.", "MESH...");
    parser.process(app);
    if (parser.positionalArguments().isEmpty())
        parser.showHelp(2);
    SkeletonOptions options;
    options.targetNodes = parser.value("target").toInt();
    std::printf("bench_skeleton, %s, %u hardware threads\n",
                qPrintable(QDateTime::currentDateTime().toString(Qt::ISODate)), std::thread::hardware_concurrency());
    for (const QString& path : parser.positionalArguments()) {
        try {
            TriangleMesh mesh = loadMesh(path.toStdString());
            if (const int levels = parser.value("subdivide").toInt(); levels > 0)
                mesh = loopSubdivide(mesh, levels);
            std::printf("%s: %zu vertices, %zu triangles\n", qPrintable(path), mesh.vertexCount(),
                        mesh.triangleCount());
            printExtraction(mesh, options);
            if (parser.isSet("orderings"))
                printOrderings(mesh, options.contraction);
        } catch (const std::exception& e) {
            std::printf("%s: %s\n", qPrintable(path), e.what());
        }
    }
    return 0;
}
