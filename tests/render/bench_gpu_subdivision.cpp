// Benchmark of one control-point edit of a subdivision surface, CPU against GPU, side by
// side in one run: the torus cage (16 × 8 quads) at limit level 5, 131,072 vertices, one
// control point moved per edit (a different one each time, back and forth), the median
// time of an edit
// - on the CPU, as the viewport showed a drag before the GPU path: SubdivisionSurface::update
//   (the stencils of the moved point's support only) plus GpuScene::updatePositions (float
//   positions of the whole object, CPU normals, upload), and
// - on the GPU: GpuSubdivision::evaluate (the control points uploaded, OpenSubdiv's stencil
//   kernel over every output vertex, the normal pass),
// each followed by glFinish, so both include the GPU's work. Then the CPU path alone, as a
// viewport without the GPU evaluator runs it (no GPU write to the positions between two
// uploads), with the CPU normals timed apart: on an NVIDIA H200 an upload that follows a GPU
// evaluation of the same buffer took 154 ms for 131,072 vertices, which a drag without the
// GPU path should not pay. The CPU normals are timed twice per edit: as the last glFinish
// left the CPU, and after render::leaveWideVectorState() (render/gl/wide_vector_state.h:
// NVIDIA's driver leaves the upper vector halves in use, and baseline SSE code then runs
// about 9x slower; TrimLab's own calls into the driver end that state, a bare glFinish does
// not). Not a test: times only.
//
//   xvfb-run -a ./build/tests/render/bench_gpu_subdivision [LEVEL [EDITS]]   (default 5 21)
#include "render/frame/gpu_scene.h"
#include "render/frame/gpu_subdivision.h"
#include "render/frame/subdivision_stencils.h"
#include "render/gl/offscreen_gl_context.h"
#include "render/gl/wide_vector_state.h"
#include "render/trim_renderer.h"

#include "core/mesh/triangle_mesh.h"
#include "core/surface/subdivision_cages.h"
#include "core/surface/subdivision_surface.h"

#include <QGuiApplication>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

using namespace trimlab;

namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

struct EditTimes {
    std::vector<double> cpuStencils;
    std::vector<double> cpuUpload;
    std::vector<double> gpu;
};

// Edit e: control point e mod #C moves out and, on the next round, back. Returns it.
std::uint32_t applyEdit(std::vector<glm::dvec3>& points, int e)
{
    const std::uint32_t moved = std::uint32_t(e) % std::uint32_t(points.size());
    points[moved] += (e / int(points.size())) % 2 == 0 ? glm::dvec3(0.05, 0.08, -0.03) : glm::dvec3(-0.05, -0.08, 0.03);
    return moved;
}

// Edits as applyEdit makes them: CPU and GPU take
// turns edit by edit, so a busy machine slows both alike. The first edit (shader JIT) is
// not counted.
EditTimes timeEdits(render::TrimRenderer& renderer, SubdivisionSurface& surface, const SubdivisionCage& cage, int edits)
{
    render::GpuSubdivision gpu(renderer.gl(), render::subdivisionStencils(surface));
    render::GpuScene& scene = renderer.gpuScene();
    std::vector<glm::dvec3> points = cage.positions;
    EditTimes times;
    for (int e = 0; e <= edits; ++e) {
        const std::uint32_t moved = applyEdit(points, e);
        auto start = std::chrono::steady_clock::now();
        surface.update(points, std::span(&moved, 1));
        const double stencils = millisecondsSince(start);
        start = std::chrono::steady_clock::now();
        scene.updatePositions(0, surface.mesh().positions);
        renderer.gl().glFinish();
        const double upload = millisecondsSince(start);
        start = std::chrono::steady_clock::now();
        gpu.evaluate(scene, 0, points);
        renderer.gl().glFinish();
        const double onGpu = millisecondsSince(start);
        if (e == 0)
            continue;
        times.cpuStencils.push_back(stencils);
        times.cpuUpload.push_back(upload);
        times.gpu.push_back(onGpu);
    }
    return times;
}

struct CpuPathTimes {
    std::vector<double> normals;     // vertexNormals of the new positions (part of the upload)
    std::vector<double> normalsLeft; // the same after leaveWideVectorState()
    std::vector<double> upload;      // GpuScene::updatePositions + glFinish
};

CpuPathTimes timeCpuPathAlone(render::TrimRenderer& renderer, SubdivisionSurface& surface, const SubdivisionCage& cage,
                              int edits)
{
    render::GpuScene& scene = renderer.gpuScene();
    std::vector<glm::dvec3> points = cage.positions;
    CpuPathTimes times;
    for (int e = 0; e <= edits; ++e) {
        const std::uint32_t moved = applyEdit(points, e);
        surface.update(points, std::span(&moved, 1));
        auto start = std::chrono::steady_clock::now();
        const std::vector<glm::vec3> normals = vertexNormals(surface.mesh());
        const double normalTime = millisecondsSince(start);
        render::leaveWideVectorState();
        start = std::chrono::steady_clock::now();
        const std::vector<glm::vec3> normalsAgain = vertexNormals(surface.mesh());
        const double normalLeftTime = millisecondsSince(start);
        start = std::chrono::steady_clock::now();
        scene.updatePositions(0, surface.mesh().positions);
        renderer.gl().glFinish();
        if (e == 0 || normals.empty() || normalsAgain.empty())
            continue;
        times.upload.push_back(millisecondsSince(start));
        times.normals.push_back(normalTime);
        times.normalsLeft.push_back(normalLeftTime);
    }
    return times;
}

// Whether a bare glFinish leaves the wide-vector state in use, where the CPU can tell.
std::string stateAfterFinish(render::TrimRenderer& renderer)
{
    render::leaveWideVectorState();
    renderer.gl().glFinish();
    const std::optional<bool> inUse = render::wideVectorStateInUse();
    return !inUse ? "unknown" : *inUse ? "in use" : "not in use";
}

} // namespace

int main(int argc, char** argv)
{
    QGuiApplication app(argc, argv);
    const int level = argc > 1 ? std::atoi(argv[1]) : 5;
    const int edits = argc > 2 ? std::max(1, std::atoi(argv[2])) : 21;
    render::OffscreenGlContext context;
    render::TrimRenderer renderer(context.context());
    std::printf("OpenGL: %s\n", qPrintable(context.capabilities().renderer));

    const SubdivisionCage cage = torusCage();
    const auto built = std::chrono::steady_clock::now();
    SubdivisionSurface surface(cage, {level, SubdivisionMode::Limit});
    std::printf("torus cage, %zu control points, limit level %d: %zu vertices, %zu triangles, %zu stencil entries "
                "(built in %.0f ms)\n",
                cage.vertexCount(), level, surface.positions().size(), surface.mesh().triangles.size(),
                surface.stencilEntryCount(), millisecondsSince(built));
    Scene scene;
    scene.objects.push_back({"torus", surface.mesh(), glm::dmat4(1.0)});
    renderer.setScene(scene);

    const EditTimes times = timeEdits(renderer, surface, cage, edits);
    const double cpu = median(times.cpuStencils) + median(times.cpuUpload);
    const double gpu = median(times.gpu);
    std::printf("ms per edit, median of %d: CPU stencils %.3f + upload %.3f = %.3f | GPU %.3f | CPU/GPU %.2f\n", edits,
                median(times.cpuStencils), median(times.cpuUpload), cpu, gpu, gpu > 0.0 ? cpu / gpu : 0.0);
    const CpuPathTimes alone = timeCpuPathAlone(renderer, surface, cage, edits);
    std::printf("CPU path alone, median of %d: upload %.3f ms (of which CPU normals %.3f) | upload after a GPU "
                "evaluation / alone %.2f\n",
                edits, median(alone.upload), median(alone.normals),
                median(alone.upload) > 0.0 ? median(times.cpuUpload) / median(alone.upload) : 0.0);
    std::printf("CPU normals as glFinish left the CPU %.3f ms | after leaveWideVectorState %.3f ms | ratio %.2f "
                "(wide-vector state %s after glFinish)\n",
                median(alone.normals), median(alone.normalsLeft),
                median(alone.normalsLeft) > 0.0 ? median(alone.normals) / median(alone.normalsLeft) : 0.0,
                stateAfterFinish(renderer).c_str());
    return 0;
}
