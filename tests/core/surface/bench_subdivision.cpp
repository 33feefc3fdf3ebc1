// Subdivision surface timings (not a test: it never fails on speed and is not registered
// with CTest). Run by hand, e.g.
//   build-subd/tests/core/surface/bench_subdivision            (torus 16×8 cage, level 5, limit)
//   build-subd/tests/core/surface/bench_subdivision --ring 16 --tube 8 --level 5 --repeats 9
//   ... --obj torus.obj   also writes the limit mesh, to time trimming it with trimlab render
// For a torus cage it prints the output size, the time to build the stencil tables (once
// per topology), one re-evaluation after moving one cage vertex (update(), only its
// support) and after moving all (evaluate()), and, for comparison, re-running OpenSubdiv
// from scratch per edit (TopologyRefiner + PrimvarRefiner uniform refinement, plus
// PrimvarRefiner::Limit in limit mode) — medians of the repeats, with ratios.
#include "uniform_refinement.h"

#include "core/mesh/obj_writer.h"
#include "core/surface/subdivision_cages.h"
#include "core/surface/subdivision_surface.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <functional>
#include <memory>
#include <vector>

using namespace trimlab;

namespace {

double medianMs(int repeats, const std::function<void(int)>& run)
{
    std::vector<double> ms;
    for (int r = 0; r < repeats; ++r) {
        QElapsedTimer timer;
        timer.start();
        run(r);
        ms.push_back(double(timer.nsecsElapsed()) * 1e-6);
    }
    std::sort(ms.begin(), ms.end());
    return ms[ms.size() / 2];
}

// What an edit would cost without stencils: build the refiner and refine the positions;
// with `limit`, also push the refined vertices to the limit with tangents
// (PrimvarRefiner::Limit: the same points as limit mode on smooth cages).
std::size_t refineFromScratch(const SubdivisionCage& cage, int level, bool limit)
{
    const test::UniformRefinement refined = test::refineUniformly(cage, level, limit);
    if (limit)
        (void)test::limitOfRefined(refined);
    return refined.points.size();
}

void run(int ring, int tube, int level, SubdivisionMode mode, int repeats)
{
    SubdivisionCage cage = torusCage(ring, tube);
    const SubdivisionSettings settings{level, mode};
    std::unique_ptr<SubdivisionSurface> surface;
    const double buildMs = medianMs(std::max(1, repeats / 3),
                                    [&](int) { surface = std::make_unique<SubdivisionSurface>(cage, settings); });
    const std::uint32_t moved = 5;
    const std::uint32_t movedList[] = {moved};
    std::size_t changed = 0;
    const double oneMs = medianMs(repeats, [&](int r) {
        cage.positions[moved].z += (r % 2 == 0 ? 0.01 : -0.01);
        changed = surface->update(cage.positions, movedList).size();
    });
    const double allMs = medianMs(repeats, [&](int r) {
        for (glm::dvec3& p : cage.positions)
            p *= (r % 2 == 0 ? 1.001 : 1.0 / 1.001);
        surface->evaluate(cage.positions);
    });
    const bool limit = mode == SubdivisionMode::Limit;
    const double scratchMs = medianMs(repeats, [&](int) { (void)refineFromScratch(cage, level, limit); });
    std::printf("torus %dx%d cage (%zu vertices), level %d, %s mode\n", ring, tube, cage.vertexCount(), level,
                mode == SubdivisionMode::Limit ? "limit" : "uniform");
    std::printf("  output: %zu vertices, %zu triangles; %zu stencil entries (%.1f per vertex), %.1f MiB\n",
                surface->mesh().vertexCount(), surface->mesh().triangleCount(), surface->stencilEntryCount(),
                double(surface->stencilEntryCount()) / double(surface->mesh().vertexCount()),
                double(surface->stencilEntryCount() * sizeof(StencilWeight)) / (1024.0 * 1024.0));
    std::printf("  table build (once per topology): %9.2f ms\n", buildMs);
    std::printf("  move 1 cage vertex  (update):    %9.3f ms  (%zu output vertices moved)\n", oneMs, changed);
    std::printf("  move all cage vertices (evaluate): %7.2f ms\n", allMs);
    std::printf("  Far refinement from scratch:        %5.2f ms  (%s, no normals)\n", scratchMs,
                limit ? "refine + PrimvarRefiner::Limit with tangents" : "refined positions");
    std::printf("  ratios: scratch / one-vertex edit = %.1fx, scratch / full evaluate = %.1fx\n", scratchMs / oneMs,
                scratchMs / allMs);
}

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    QCommandLineParser parser;
    parser.setApplicationDescription("Subdivision surface stencil-table timings");
    parser.addHelpOption();
    parser.addOption({"ring", "torus ring segments", "n", "16"});
    parser.addOption({"tube", "torus tube segments", "n", "8"});
    parser.addOption({"level", "subdivision level (0-5)", "n", "5"});
    parser.addOption({"repeats", "repeats per measurement (median)", "n", "9"});
    parser.addOption({"uniform", "also time uniform mode"});
    parser.addOption({"obj", "also write the limit surface's mesh (to time trimming it with trimlab render)", "file"});
    parser.process(app);
    try {
        const int ring = parser.value("ring").toInt(), tube = parser.value("tube").toInt();
        const int level = parser.value("level").toInt(), repeats = std::max(1, parser.value("repeats").toInt());
        run(ring, tube, level, SubdivisionMode::Limit, repeats);
        if (parser.isSet("uniform"))
            run(ring, tube, level, SubdivisionMode::Uniform, repeats);
        if (parser.isSet("obj")) {
            const SubdivisionSurface surface(torusCage(ring, tube), {level, SubdivisionMode::Limit});
            saveMeshObj(parser.value("obj").toStdString(), surface.mesh(), {},
                        "torus cage limit surface, level " + std::to_string(level));
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_subdivision: %s\n", e.what());
        return 1;
    }
    return 0;
}
