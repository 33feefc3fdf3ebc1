// NURBS re-evaluation timings (not a test: it never fails on speed and is not registered
// with CTest). Run by hand:
//   build-nurbs/tests/core/surface/bench_nurbs [segmentsU segmentsV] [--json] [--obj sphere.obj]
// (--obj also writes the sphere's tessellation, to time trimming it with `trimlab render
// sphere.obj --repeat N`).
// For the exact rational sphere and torus tessellated at segmentsU × segmentsV intervals
// (default 256 × 200: ≥ 100k triangles) it prints, as the median of repeated runs:
//  - build:        NurbsTessellation constructor (span search, basis tables, topology, first evaluation)
//  - edit one:     moveControlPoint + update(surface, {k}) for one interior control point
//  - edit all:     every control point moved, update(surface) (separable full mat-vec)
//  - edit all (sparse): the same through update(surface, all indices)
//  - scratch:      evaluateNurbs + nurbsNormal at every vertex (span search per sample), the
//                  naive alternative the tables replace
// and the moved-vertex count of the one-point edit, the table size and the agreement of the
// sparse result with a tessellation built from scratch.
#include "core/mesh/obj_writer.h"
#include "core/surface/nurbs_primitives.h"
#include "core/surface/nurbs_tessellation.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <thread>
#include <vector>

using namespace trimlab;

namespace {

double medianMs(int runs, const std::function<void()>& work)
{
    std::vector<double> times;
    for (int r = 0; r < runs; ++r) {
        const auto start = std::chrono::steady_clock::now();
        work();
        times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

struct Row {
    std::string name;
    std::size_t vertices = 0, triangles = 0, moved = 0, tableBytes = 0;
    double buildMs = 0, oneMs = 0, allMs = 0, allSparseMs = 0, scratchMs = 0, maxDifference = 0;
};

Row measure(const std::string& name, NurbsSurface surface, int segmentsU, int segmentsV)
{
    Row row;
    row.name = name;
    NurbsTessellation t;
    row.buildMs = medianMs(5, [&] { t = NurbsTessellation(surface, segmentsU, segmentsV); });
    row.vertices = t.mesh().vertexCount();
    row.triangles = t.mesh().triangleCount();
    row.tableBytes = t.tableBytes();
    // One interior control point, moved back and forth.
    const std::size_t k = surface.index(3, 2);
    const glm::dvec3 home = surface.points[k];
    int flip = 0;
    row.oneMs = medianMs(51, [&] {
        moveControlPoint(surface, k, home + (++flip % 2 ? 1.0 : 0.0) * glm::dvec3(0.2, 0.1, -0.3));
        const std::size_t changed[] = {k};
        row.moved = t.update(surface, changed).size();
    });
    // Every control point (a uniform scale keeps seams and poles tied).
    std::vector<std::size_t> all(surface.points.size());
    for (std::size_t c = 0; c < all.size(); ++c)
        all[c] = c;
    row.allMs = medianMs(11, [&] {
        for (glm::dvec3& p : surface.points)
            p *= 1.001;
        t.update(surface);
    });
    row.allSparseMs = medianMs(11, [&] {
        for (glm::dvec3& p : surface.points)
            p *= 1.001;
        t.update(surface, all);
    });
    row.scratchMs = medianMs(3, [&] {
        double sink = 0.0;
        for (std::uint32_t v = 0; v < t.mesh().vertexCount(); ++v) {
            const glm::dvec2 uv = t.vertexParameters(v);
            sink += evaluateNurbs(surface, uv.x, uv.y).position.x + nurbsNormal(surface, uv.x, uv.y).x;
        }
        if (sink == 1e300)
            std::puts("");
    });
    const NurbsTessellation fresh(surface, segmentsU, segmentsV);
    for (std::size_t v = 0; v < row.vertices; ++v)
        row.maxDifference =
            std::max(row.maxDifference, glm::length(t.positionsDouble()[v] - fresh.positionsDouble()[v]));
    return row;
}

} // namespace

int main(int argc, char** argv)
{
    int segmentsU = 256, segmentsV = 200;
    bool json = false;
    const char* objPath = nullptr;
    std::vector<int> numbers;
    for (int a = 1; a < argc; ++a) {
        if (std::strcmp(argv[a], "--json") == 0)
            json = true;
        else if (std::strcmp(argv[a], "--obj") == 0 && a + 1 < argc)
            objPath = argv[++a];
        else
            numbers.push_back(std::atoi(argv[a]));
    }
    if (numbers.size() == 2) {
        segmentsU = numbers[0];
        segmentsV = numbers[1];
    }
    std::printf("bench_nurbs, %d × %d segments, %u hardware threads (single-threaded code), ms = median\n", segmentsU,
                segmentsV, std::thread::hardware_concurrency());
    std::vector<Row> rows;
    try {
        rows.push_back(measure("sphere", makeNurbsSphere({0, 0, 0}, 1.0), segmentsU, segmentsV));
        rows.push_back(measure("torus", makeNurbsTorus({0, 0, 0}, 2.0, 0.6), segmentsU, segmentsV));
    } catch (const std::exception& e) {
        std::printf("bench_nurbs: %s\n", e.what());
        return 1;
    }
    // The sphere's tessellation for timing the trim renderer on it (trimlab render --repeat).
    if (objPath != nullptr)
        saveMeshObj(objPath, NurbsTessellation(makeNurbsSphere({0, 0, 0}, 1.0), segmentsU, segmentsV).mesh(), {},
                    "NURBS unit sphere, " + std::to_string(segmentsU) + " x " + std::to_string(segmentsV) +
                        " segments");
    std::printf("%-7s %8s %8s %9s %9s %8s %9s %11s %9s %8s %10s\n", "surface", "verts", "tris", "build", "edit one",
                "moved", "edit all", "all sparse", "scratch", "tableKB", "|Δ| fresh");
    for (const Row& r : rows)
        std::printf("%-7s %8zu %8zu %9.2f %9.3f %8zu %9.2f %11.2f %9.2f %8.1f %10.1e\n", r.name.c_str(), r.vertices,
                    r.triangles, r.buildMs, r.oneMs, r.moved, r.allMs, r.allSparseMs, r.scratchMs,
                    double(r.tableBytes) / 1024.0, r.maxDifference);
    if (json)
        for (const Row& r : rows)
            std::printf("{\"surface\": \"%s\", \"vertices\": %zu, \"triangles\": %zu, \"build_ms\": %.3f, "
                        "\"edit_one_ms\": %.4f, \"moved\": %zu, \"edit_all_ms\": %.3f, \"edit_all_sparse_ms\": %.3f, "
                        "\"scratch_ms\": %.3f, \"table_bytes\": %zu}\n",
                        r.name.c_str(), r.vertices, r.triangles, r.buildMs, r.oneMs, r.moved, r.allMs, r.allSparseMs,
                        r.scratchMs, r.tableBytes);
    return 0;
}
