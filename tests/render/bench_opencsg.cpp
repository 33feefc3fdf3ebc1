// Benchmark: OpenCSG — the image-based CSG behind OpenSCAD's preview (Goldfeather, which
// takes concave solids) — timed beside TrimLab's buffer methods on the same GPU, the same
// CSG expressions of three closed, non-self-crossing operands (the elephant, the
// high-resolution bunny and the bunny of the shared data, placed across each other) and
// the same views. Both are timed the same way: the median GL_TIME_ELAPSED of repeated
// frames after a warm-up, readbacks excluded. Every image is compared with the exact CPU
// reference: TrimLab's per pixel (primitive, object, facing, winding: the render tests'
// agreement) and both by depth (covered alike, view depths within 0.1 %; OpenCSG decides
// by 24-bit window depths, so about a pixel's band along intersection curves may differ).
//
// What OpenCSG cannot do is said, not measured: self-crossing operands trimmed by a rule
// (the goal scene csg3-500k's dragon), clipping planes with caps, per-object windings of
// collision highlighting — it computes the CSG of ordinary closed solids only.
//
//   xvfb-run -a ./build/tests/render/bench_opencsg [--size WxH[,WxH]] [--views N] [--repeat N]
#include "opencsg_depth.h"
#include "test_paths.h"
#include "view_directions.h"

#include "core/catalog/scene_source.h"
#include "core/scene/object_transform.h"
#include "core/scene/world_geometry.h"
#include "core/trim/csg_expression.h"
#include "core/trim/reference_renderer.h"
#include "core/trim/trim_agreement.h"
#include "render/frame_times.h"
#include "render/gl/gl_error.h"
#include "render/gl/offscreen_gl_context.h"
#include "render/trim_renderer.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

using namespace trimlab;

namespace {

struct Options {
    std::vector<QSize> sizes{QSize(1024, 768)};
    int views = 4;
    int repeat = 5;
};

/// One row: a CSG expression over the scene's objects and the same set as OpenCSG's sum of
/// products.
struct CsgRow {
    const char* expression;
    std::vector<test::OpenCsgProduct> products;
};

struct View {
    Camera camera;
    ReferenceResult reference;
};

/// Pixels covered by either image, and those covered by both at view depths within 0.1 %.
struct DepthAgreement {
    long covered = 0;
    long agreeing = 0;
    void add(const DepthAgreement& other)
    {
        covered += other.covered;
        agreeing += other.agreeing;
    }
    [[nodiscard]] double percent() const { return covered > 0 ? 100.0 * double(agreeing) / double(covered) : 0.0; }
};

constexpr double kRelativeDepthTolerance = 1e-3;

std::optional<Options> parseOptions(const QStringList& arguments)
{
    Options options;
    for (qsizetype i = 1; i < arguments.size(); ++i) {
        const QString& argument = arguments[i];
        const QString value = i + 1 < arguments.size() ? arguments[i + 1] : QString();
        bool ok = true;
        if (argument == QLatin1String("--size")) {
            options.sizes.clear();
            for (const QString& size : value.split(QLatin1Char(','))) {
                const QStringList sides = size.split(QLatin1Char('x'));
                if (sides.size() != 2)
                    return std::nullopt;
                options.sizes.emplace_back(sides[0].toInt(&ok), sides[1].toInt(&ok));
                if (!ok || options.sizes.back().isEmpty())
                    return std::nullopt;
            }
        } else if (argument == QLatin1String("--views")) {
            options.views = value.toInt(&ok);
        } else if (argument == QLatin1String("--repeat")) {
            options.repeat = value.toInt(&ok);
        } else {
            return std::nullopt;
        }
        if (!ok || options.views < 1 || options.repeat < 1)
            return std::nullopt;
        ++i;
    }
    return options;
}

/// The elephant (0) with the high-resolution bunny (1) and the bunny (2) placed across it,
/// each 0.55 of the elephant's size, as the goal scene places its operands.
Scene closedTrio()
{
    Scene scene = loadScene(test::sharedDataPath("anim/elephant-gallop/elephant-gallop-05.obj.gz").string()).scene;
    const Bounds bounds = scene.worldBounds();
    const glm::dvec3 extent = bounds.max - bounds.min;
    const double size = std::max({extent.x, extent.y, extent.z});
    const glm::dvec3 offset(0.2 * extent.x, 0.0, 0.0);
    const std::pair<const char*, glm::dvec3> others[] = {
        {"static/odedstein-bunny_hr.obj.gz", bounds.center() + offset},
        {"static/odedstein-bunny.obj.gz", bounds.center() - offset},
    };
    for (const auto& [file, center] : others) {
        SceneObject object = std::move(loadScene(test::sharedDataPath(file).string()).scene.objects.at(0));
        object.modelMatrix = fitIntoCube(computeBounds(object.mesh), center, 0.55 * size);
        scene.objects.push_back(std::move(object));
    }
    return scene;
}

/// Each object as an ordinary solid (positive index), combined by `expression`.
TrimSettings csgSettings(const char* expression)
{
    TrimSettings settings;
    settings.rule = StaticRule::PositiveIndex;
    settings.csg.expression = parseCsgExpression(expression, nullptr).value();
    for (auto& rule : settings.csg.objectRules)
        rule = StaticRule::PositiveIndex;
    return settings;
}

/// OpenCSG's convexity of each object: the most front faces a ray of any view crosses (half
/// the most hits of a closed surface at a quarter of the size), one more for the rays in
/// between.
std::vector<test::OpenCsgSolid> openCsgSolids(const Scene& scene, const std::vector<View>& views, QSize size)
{
    std::vector<test::OpenCsgSolid> solids;
    for (const SceneObject& object : scene.objects) {
        Scene alone;
        alone.objects.push_back(object);
        const ReferenceRenderer reference(alone);
        int hits = 0;
        for (const View& view : views)
            hits = std::max(hits, int(reference
                                          .render(view.camera, std::max(1, size.width() / 4),
                                                  std::max(1, size.height() / 4), TrimSettings{})
                                          .stats.maxHitsPerPixel));
        test::OpenCsgSolid solid;
        solid.convexity = unsigned((hits + 1) / 2 + 1);
        const std::vector<glm::dvec3> world = worldPositions(object);
        for (const glm::uvec3& t : object.mesh.triangles)
            for (int k = 0; k < 3; ++k)
                solid.corners.push_back(world[t[k]]);
        solids.push_back(std::move(solid));
    }
    return solids;
}

DepthAgreement depthAgreement(const std::vector<double>& depth, const TrimImage& reference)
{
    DepthAgreement agreement;
    for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
        const TrimPixel& p = reference.pixels[i];
        const bool ours = std::isfinite(depth[i]);
        if (!ours && !p.covered())
            continue;
        ++agreement.covered;
        if (ours && p.covered() && std::abs(depth[i] - double(p.viewDepth)) <= kRelativeDepthTolerance * p.viewDepth)
            ++agreement.agreeing;
    }
    return agreement;
}

std::vector<double> trimDepth(const TrimImage& image)
{
    std::vector<double> depth(image.pixels.size(), INFINITY);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        if (image.pixels[i].covered())
            depth[i] = image.pixels[i].viewDepth;
    return depth;
}

struct Cell {
    std::string method;
    render::FrameTimes times;
    std::vector<double> gpuMs; ///< OpenCSG's frames
    std::optional<TrimAgreement> exact;
    DepthAgreement depth;
    std::string error;
    [[nodiscard]] double milliseconds() const
    {
        return gpuMs.empty() ? times.medianMilliseconds() : render::medianOf(gpuMs);
    }
};

Cell measureTrimLab(render::TrimRenderer& renderer, render::FragmentMethodKind method, const TrimSettings& settings,
                    const std::vector<View>& views, QSize size, const ReferenceRenderer& reference, int repeat)
{
    Cell cell;
    cell.method = std::string(render::methodInfo(method).id);
    try {
        renderer.setMethod(method);
        renderer.render(views.front().camera, settings, size.width(), size.height()); // shaders, storage
        TrimAgreement exact;
        for (const View& view : views) {
            for (int frame = 0; frame < repeat; ++frame) {
                renderer.render(view.camera, settings, size.width(), size.height());
                cell.times.add(renderer.lastStats());
            }
            const TrimImage image = renderer.readTrimImage();
            exact.add(
                measureTrimAgreement(image, view.reference.trim, view.reference.diagnostics, {},
                                     referenceTieCheck(reference, view.camera, size.width(), size.height(), settings)));
            cell.depth.add(depthAgreement(trimDepth(image), view.reference.trim));
        }
        cell.exact = exact;
    } catch (const std::exception& e) {
        cell.error = e.what();
    }
    return cell;
}

Cell measureOpenCsg(const std::vector<test::OpenCsgSolid>& solids, const CsgRow& row, const std::vector<View>& views,
                    QSize size, int repeat)
{
    Cell cell;
    cell.method = "OpenCSG (Goldfeather)";
    test::OpenCsgRenderer renderer(solids, row.products, size.width(), size.height());
    if (!renderer.error().empty()) {
        cell.error = renderer.error();
        return cell;
    }
    const double aspect = double(size.width()) / double(size.height());
    (void)renderer.render(viewMatrix(views.front().camera), projectionMatrix(views.front().camera, aspect));
    for (const View& view : views) {
        const glm::dmat4 projection = projectionMatrix(view.camera, aspect);
        for (int frame = 0; frame < repeat; ++frame)
            cell.gpuMs.push_back(renderer.render(viewMatrix(view.camera), projection));
        std::vector<double> depth(renderer.depth().size(), INFINITY);
        for (std::size_t i = 0; i < depth.size(); ++i)
            if (renderer.depth()[i] < 1.0f)
                depth[i] = test::openCsgViewDepth(renderer.depth()[i], view.camera.zNear, view.camera.zFar);
        cell.depth.add(depthAgreement(depth, view.reference.trim));
    }
    return cell;
}

void printCell(const char* expression, QSize size, const Cell& cell, const Cell& openCsg)
{
    const std::string sizeText = std::to_string(size.width()) + "x" + std::to_string(size.height());
    if (!cell.error.empty()) {
        std::printf("%-12s %-10s %-22s  failed: %s\n", expression, sizeText.c_str(), cell.method.c_str(),
                    cell.error.substr(0, cell.error.find('\n')).c_str());
        return;
    }
    const double ms = cell.milliseconds();
    const std::string exact = cell.exact ? std::to_string(100.0 * cell.exact->agreement()).substr(0, 7) : "-";
    const double base = openCsg.error.empty() ? openCsg.milliseconds() : 0.0;
    const std::string ratio = base > 0.0 && ms > 0.0 ? std::to_string(ms / base).substr(0, 5) : "n/a";
    std::printf("%-12s %-10s %-22s %9.2f %4s %8.0f %9s %9.3f %9s\n", expression, sizeText.c_str(), cell.method.c_str(),
                ms, cell.gpuMs.empty() ? std::string(cell.times.source()).c_str() : "GPU", ms > 0.0 ? 1000.0 / ms : 0.0,
                exact.c_str(), cell.depth.percent(), ratio.c_str());
}

} // namespace

int main(int argc, char** argv)
{
    QGuiApplication app(argc, argv);
    const std::optional<Options> options = parseOptions(app.arguments());
    if (!options) {
        std::fprintf(stderr, "usage: bench_opencsg [--size WxH[,WxH]] [--views N] [--repeat N]\n");
        return 2;
    }
    try {
        render::OffscreenGlContext core;
        core.makeCurrent();
        render::TrimRenderer renderer(core.context());
        // OpenCSG needs the fixed-function pipeline: a compatibility context of its own.
        QSurfaceFormat format;
        format.setVersion(2, 1);
        format.setDepthBufferSize(24);
        format.setStencilBufferSize(8);
        QOffscreenSurface legacySurface;
        legacySurface.setFormat(format);
        legacySurface.create();
        QOpenGLContext legacy;
        legacy.setFormat(format);
        if (!legacy.create() || !legacy.makeCurrent(&legacySurface))
            throw std::runtime_error("no OpenGL compatibility context for OpenCSG");
        core.makeCurrent();

        const Scene scene = closedTrio();
        renderer.setScene(scene);
        std::printf("OpenGL: %s\n", qPrintable(renderer.capabilities().summary()));
        std::printf("scene: elephant (%zu triangles) with the bunny-hr (%zu) and the bunny (%zu) across it\n",
                    scene.objects[0].mesh.triangles.size(), scene.objects[1].mesh.triangles.size(),
                    scene.objects[2].mesh.triangles.size());
        std::printf("%d views x %d frames after a warm-up; ms/frame: median GL_TIME_ELAPSED; exact %%: TrimLab's "
                    "per-pixel agreement with the CPU reference; depth %%: pixels covered by either with equal "
                    "coverage and view depth within 0.1 %%; vs OpenCSG: time / OpenCSG's\n",
                    options->views, options->repeat);
        std::printf("not measured: csg3-500k (its dragon operand crosses itself and is trimmed by the alternating "
                    "border rule; the scene is clipped and capped) - OpenCSG computes the CSG of ordinary closed "
                    "solids, with no self-trimming, clipping caps or per-object windings\n\n");
        std::printf("%-12s %-10s %-22s %9s %4s %8s %9s %9s %9s\n", "expression", "size", "method", "ms/frame", "time",
                    "fps", "exact %", "depth %", "vs OpenCSG");
        const std::vector<CsgRow> rows = {
            {"0 - 1 - 2", {{{0}, {1, 2}}}},
            {"0 & 1", {{{0, 1}, {}}}},
            {"(0 | 1) - 2", {{{0}, {2}}, {{1}, {2}}}},
        };
        const std::vector<render::FragmentMethodKind> methods = {
            render::FragmentMethodKind::KPlusArray,   render::FragmentMethodKind::KPlusHeap,
            render::FragmentMethodKind::KPlusSBuffer, render::FragmentMethodKind::SBuffer,
            render::FragmentMethodKind::ABufferFixed, render::FragmentMethodKind::ABufferLinkedList,
        };
        for (const QSize size : options->sizes) {
            const double aspect = double(size.width()) / double(size.height());
            std::vector<View> views;
            for (int i = 0; i < options->views; ++i)
                views.push_back(
                    {fitCamera(scene.worldBounds(), aspect, test::fibonacciDirection(i, options->views)), {}});
            const std::vector<test::OpenCsgSolid> solids = openCsgSolids(scene, views, size);
            const ReferenceRenderer reference(scene);
            for (const CsgRow& row : rows) {
                const TrimSettings settings = csgSettings(row.expression);
                for (View& view : views)
                    view.reference = reference.render(view.camera, size.width(), size.height(), settings);
                legacy.makeCurrent(&legacySurface);
                const Cell openCsg = measureOpenCsg(solids, row, views, size, options->repeat);
                legacy.doneCurrent();
                core.makeCurrent();
                printCell(row.expression, size, openCsg, openCsg);
                for (const render::FragmentMethodKind method : methods)
                    printCell(row.expression, size,
                              measureTrimLab(renderer, method, settings, views, size, reference, options->repeat),
                              openCsg);
                std::fflush(stdout);
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_opencsg: %s\n", e.what());
        return 1;
    }
    return 0;
}
