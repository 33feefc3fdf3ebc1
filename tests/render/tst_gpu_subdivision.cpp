// Subdivision surfaces evaluated on the GPU (render/frame/gpu_subdivision.h, OpenSubdiv's
// GLSL compute evaluator) against the CPU's stencil evaluation (SubdivisionSurface): the
// positions read back from the scene's buffer equal the CPU's within 1e-5 of the bounding
// box's diagonal — for a cube, a cube with creases and a sharp corner, the T shape
// (valence 3 and 5) and the octahedron under Loop, limit and uniform, at levels 1 to 3,
// before and after a control-point edit — and the normals equal vertexNormals of those
// positions; a GPU-evaluated self-intersecting edit trims like the exact CPU reference of
// the CPU's positions on two buffer methods; and the viewport's renderer evaluates an edit
// on the GPU (again in a new context) and falls back to the CPU's positions for stencils
// that do not fit.
#include "buffer_readback.h"
#include "gl_test_context.h"
#include "method_check.h"

#include "render/frame/gpu_scene.h"
#include "render/frame/gpu_subdivision.h"
#include "render/frame/subdivision_stencils.h"
#include "render/content_publisher.h"
#include "render/viewport_renderer.h"

#include "core/surface/subdivision_cages.h"
#include "core/surface/subdivision_surface.h"
#include "core/trim/reference_renderer.h"

#include <QtTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <functional>
#include <memory>

using namespace trimlab;
using namespace trimlab::render;

namespace {

// The cube with creases on its first face's edges (two infinitely sharp, one of sharpness
// 1.5) and a sharp corner.
SubdivisionCage creasedCube()
{
    SubdivisionCage cage = cubeCage();
    const std::span<const std::uint32_t> f = cage.face(0);
    cage.creases = {{f[0], f[1]}, {f[1], f[2]}, {f[2], f[3], 1.5f}};
    cage.corners = {{f[3]}};
    return cage;
}

struct SurfaceCase {
    QString name;
    std::function<SubdivisionCage()> cage;
    SubdivisionSettings settings;
    std::uint32_t edited = 0; // the control point the edit moves
};

std::vector<SurfaceCase> surfaceCases()
{
    using M = SubdivisionMode;
    const auto cube = [] { return cubeCage(); };
    return {
        {"cube limit 1", cube, {1, M::Limit}, 0},
        {"cube limit 3", cube, {3, M::Limit}, 5},
        {"cube uniform 2", cube, {2, M::Uniform}, 2},
        {"creased cube limit 2", creasedCube, {2, M::Limit}, 1},
        {"creased cube uniform 3", creasedCube, {3, M::Uniform}, 3},
        {"t-shape limit 2", tShapeCage, {2, M::Limit}, 7},
        {"t-shape uniform 1", tShapeCage, {1, M::Uniform}, 11},
        {"octahedron (Loop) limit 3", octahedronCage, {3, M::Limit}, 4},
    };
}

using test::largestDistance;

/// Pixels whose shown primitive or facing differ.
int differingPixels(const TrimImage& a, const TrimImage& b)
{
    int differ = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        differ +=
            a.pixels[i].primitiveId != b.pixels[i].primitiveId || a.pixels[i].facing != b.pixels[i].facing ? 1 : 0;
    return differ;
}

Scene sceneOf(TriangleMesh mesh)
{
    Scene scene;
    scene.objects.push_back(SceneObject{"subdivided", std::move(mesh), glm::dmat4(1.0)});
    return scene;
}

// The surface's mesh moved far away: an evaluation that wrote nothing cannot pass.
Scene displacedScene(const SubdivisionSurface& surface)
{
    TriangleMesh mesh = surface.mesh();
    for (glm::vec3& p : mesh.positions)
        p += glm::vec3(10.0f, -7.0f, 3.0f);
    return sceneOf(std::move(mesh));
}

double diagonalOf(const SubdivisionSurface& surface)
{
    return 2.0 * computeBounds(surface.mesh()).radius();
}

std::vector<glm::vec3> floatPositions(const std::vector<glm::dvec3>& positions)
{
    return {positions.begin(), positions.end()};
}

} // namespace

Q_DECLARE_METATYPE(SurfaceCase)
Q_DECLARE_METATYPE(trimlab::render::FragmentMethodKind)

class TestGpuSubdivision : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void positionsAndNormalsMatchCpu_data();
    void positionsAndNormalsMatchCpu();
    void trimMatchesReference_data();
    void trimMatchesReference();
    void viewportEvaluatesEditsOnTheGpu();
    void viewportFallsBackToTheCpusPositions();
    void viewportEvaluatesAgainInTheSameContext();
    void refusesMismatches();

private:
    /// Checks object 0 of the renderer's scene against `surface`'s CPU positions and the
    /// normals against vertexNormals of what was read; returns the position error / diagonal.
    double compareWithCpu(const SubdivisionSurface& surface, const QString& when);

    std::unique_ptr<OffscreenGlContext> m_context;
    std::unique_ptr<TrimRenderer> m_renderer;
};

void TestGpuSubdivision::initTestCase()
{
    TRIMLAB_INIT_GL_CONTEXT(m_context);
    m_renderer = std::make_unique<TrimRenderer>(m_context->context());
}

double TestGpuSubdivision::compareWithCpu(const SubdivisionSurface& surface, const QString& when)
{
    const std::vector<glm::vec3> positions = m_renderer->gpuScene().readPositions(0);
    const double diagonal = diagonalOf(surface);
    const double distance = largestDistance(positions, surface.positions());
    if (distance > 1e-5 * diagonal)
        QTest::qFail(qPrintable(QString("%1: GPU positions differ from the CPU's by %2 (diagonal %3)")
                                    .arg(when)
                                    .arg(distance)
                                    .arg(diagonal)),
                     __FILE__, __LINE__);
    const std::vector<glm::vec3> normals = m_renderer->gpuScene().readNormals(0);
    const double normalError =
        largestDistance(normals, vertexNormals(TriangleMesh{positions, surface.mesh().triangles}));
    if (normalError > 1e-6)
        QTest::qFail(qPrintable(QString("%1: GPU normals differ by %2").arg(when).arg(normalError)), __FILE__,
                     __LINE__);
    return distance / diagonal;
}

void TestGpuSubdivision::positionsAndNormalsMatchCpu_data()
{
    QTest::addColumn<SurfaceCase>("surfaceCase");
    for (const SurfaceCase& c : surfaceCases())
        QTest::newRow(qPrintable(c.name)) << c;
}

void TestGpuSubdivision::positionsAndNormalsMatchCpu()
{
    QFETCH(SurfaceCase, surfaceCase);
    const SubdivisionCage cage = surfaceCase.cage();
    SubdivisionSurface surface(cage, surfaceCase.settings);
    m_renderer->setScene(displacedScene(surface));
    GpuSubdivision gpu(m_renderer->gl(), subdivisionStencils(surface));
    gpu.evaluate(m_renderer->gpuScene(), 0, cage.positions);
    const double before = compareWithCpu(surface, "the cage as built");
    if (QTest::currentTestFailed())
        return;

    // One control point pulled out and sideways: only its support moves on the CPU.
    std::vector<glm::dvec3> edited = cage.positions;
    edited[surfaceCase.edited] += glm::dvec3(0.45, -0.3, 0.6);
    const std::vector<glm::dvec3> previous = surface.positions();
    const std::uint32_t moved[] = {surfaceCase.edited};
    surface.update(edited, moved);
    gpu.evaluate(m_renderer->gpuScene(), 0, edited);
    const double after = compareWithCpu(surface, "after the edit");
    double motion = 0.0;
    for (std::size_t v = 0; v < previous.size(); ++v)
        motion = std::max(motion, glm::length(surface.positions()[v] - previous[v]));
    QVERIFY2(motion > 0.05 * diagonalOf(surface), "the edit hardly moves the surface: the comparison says little");
    qInfo("%zu control points, %zu vertices: worst position error %.3g of the diagonal before the edit, %.3g after",
          cage.vertexCount(), surface.positions().size(), before, after);
}

void TestGpuSubdivision::trimMatchesReference_data()
{
    QTest::addColumn<FragmentMethodKind>("method");
    for (FragmentMethodKind method : {FragmentMethodKind::KPlusArray, FragmentMethodKind::ABufferLinkedList})
        QTest::newRow(methodInfo(method).id.data()) << method;
}

// The cube's top edge on the +x side pulled down through the bottom: the sheet that comes
// out below encloses winding index −1, which the positive index rule trims away.
// Evaluated on the GPU and trimmed by the GPU, against the exact reference of the CPU's
// positions.
void TestGpuSubdivision::trimMatchesReference()
{
    QFETCH(FragmentMethodKind, method);
    SubdivisionCage cage = cubeCage(0.8);
    SubdivisionSurface surface(cage, {3, SubdivisionMode::Limit});
    for (glm::dvec3& p : cage.positions)
        if (p.x > 0.0 && p.y > 0.0)
            p.y = -2.1;
    surface.evaluate(cage.positions);
    const Scene cpuScene = sceneOf(surface.mesh());
    const ReferenceRenderer reference(cpuScene);

    m_renderer->setScene(displacedScene(surface));
    GpuSubdivision gpu(m_renderer->gl(), subdivisionStencils(surface));
    gpu.evaluate(m_renderer->gpuScene(), 0, cage.positions);

    const Bounds bounds = cpuScene.worldBounds();
    test::MethodCase testCase{QTest::currentDataTag(), {}, {}, {}, 192, 144};
    Camera camera = fitCamera(bounds, 192.0 / 144.0, glm::dvec3(-0.3, 0.35, 1.0));
    camera.eye = camera.target + (camera.eye - camera.target) * 0.55; // the bounds are mostly empty: closer
    testCase.camera = withDepthRange(camera, bounds);
    testCase.settings.trimEnabled = true;
    testCase.settings.rule = StaticRule::PositiveIndex;
    const ReferenceResult expected = reference.render(testCase.camera, 192, 144, testCase.settings);
    TrimSettings untrimmed = testCase.settings;
    untrimmed.trimEnabled = false;
    const int trimmedAway = differingPixels(expected.trim, reference.render(testCase.camera, 192, 144, untrimmed).trim);
    QVERIFY2(trimmedAway > 500,
             qPrintable(QString("the trim changes %1 pixels only: a vacuous case").arg(trimmedAway)));
    QString summary;
    const auto failure =
        test::checkMethodAgainstReference(*m_renderer, method, testCase, reference, expected, &summary);
    qInfo("%s; the trim changes %d pixels", qPrintable(summary), trimmedAway);
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
}

namespace {

// The T shape at limit level 2 with control point 7 pulled out through the body: the
// scene of the cage as built, its stencils, the edited control points and the CPU's
// positions of the edit, and a camera on the whole.
struct ViewportEdit {
    static constexpr QSize kSize{128, 96};
    SubdivisionCage cage = tShapeCage();
    std::shared_ptr<const Scene> scene;
    std::shared_ptr<const SubdivisionStencils> stencils;
    std::shared_ptr<const SubdivisionStencils> otherLevel; ///< the same cage at level 1: does not fit
    std::vector<glm::dvec3> edited;
    Camera camera;
    std::vector<glm::vec3> cpu;

    ViewportEdit()
    {
        SubdivisionSurface surface(cage, {2, SubdivisionMode::Limit});
        scene = std::make_shared<const Scene>(sceneOf(surface.mesh()));
        stencils = std::make_shared<const SubdivisionStencils>(subdivisionStencils(surface));
        otherLevel = std::make_shared<const SubdivisionStencils>(
            subdivisionStencils(SubdivisionSurface(cage, {1, SubdivisionMode::Limit})));
        edited = cage.positions;
        edited[7] += glm::dvec3(0.0, 0.0, 2.5);
        const std::uint32_t moved[] = {7};
        surface.update(edited, moved);
        camera = withDepthRange(fitCamera(scene->worldBounds(), 128.0 / 96.0), scene->worldBounds());
        cpu = floatPositions(surface.positions());
    }
};

// The viewport's frame against the reference of its posed scene; the failure also says how
// far the positions on the GPU lie from the CPU's (wrong geometry or a wrong draw).
std::optional<QString> viewportAgrees(ViewportRenderer& view, const Camera& camera, QSize size, const QString& name,
                                      const std::vector<glm::vec3>& cpuPositions)
{
    if (!view.render(camera, size, 0, [](const std::string&) {}))
        return QString("no GPU frame");
    view.finishFrames();
    const ReferenceResult expected =
        ReferenceRenderer(*view.content()->posedScene()).render(camera, size.width(), size.height(), TrimSettings{});
    const test::MethodCase testCase{name, camera, TrimSettings{}, view.methodParameters(), size.width(), size.height()};
    std::optional<QString> failure = test::checkFrameAgainstReference(view.renderer(), testCase, expected, {});
    if (failure) {
        const double off = largestDistance(view.renderer().gpuScene().readPositions(0), cpuPositions);
        GlFunctions& gl = view.renderer().gl();
        GLint viewport[4] = {};
        gl.glGetIntegerv(GL_VIEWPORT, viewport);
        *failure += QString(" (GPU positions %1 from the CPU's; after the frame: GL error 0x%2, rasterizer discard %3, "
                            "scissor %4, depth test %5, cull %6, viewport %7x%8)")
                        .arg(off)
                        .arg(gl.glGetError(), 0, 16)
                        .arg(gl.glIsEnabled(GL_RASTERIZER_DISCARD))
                        .arg(gl.glIsEnabled(GL_SCISSOR_TEST))
                        .arg(gl.glIsEnabled(GL_DEPTH_TEST))
                        .arg(gl.glIsEnabled(GL_CULL_FACE))
                        .arg(viewport[2])
                        .arg(viewport[3]);
    }
    return failure;
}

} // namespace

// The viewport's path of a control-point drag: the CPU's positions and the control points
// handed over together; the frame agrees with the reference of the CPU's positions, in a
// new context too; stencils of another surface fall back to the CPU's positions.
void TestGpuSubdivision::viewportEvaluatesEditsOnTheGpu()
{
    constexpr QSize kSize = ViewportEdit::kSize;
    const ViewportEdit edit;
    const auto& [cage, scene, stencils, otherLevel, edited, camera, cpu] = edit;

    const auto content = std::make_shared<ShownContent>();
    ViewportRenderer view(content);
    content->setScene(scene);
    ContentPublisher shown(content, ContentOwner::DesignHistory);
    const auto agrees = [&](const QString& name) { return viewportAgrees(view, camera, kSize, name, cpu); };
    m_context->makeCurrent();
    view.initialize(m_context->context());
    shown.showSubdivisionPose(stencils, edited, cpu);
    std::optional<QString> failure = agrees("viewport_gpu_subdivision");
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
    QCOMPARE(view.lastPoseEvaluation(), PoseEvaluation::GpuSubdivision);

    view.release();
    {
        OffscreenGlContext second; // current until it goes, which leaves no context current
        view.initialize(second.context());
        failure = agrees("viewport_gpu_subdivision_again");
        QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
        QCOMPARE(view.lastPoseEvaluation(), PoseEvaluation::GpuSubdivision);
        view.release();
    }
    m_context->makeCurrent();
    view.initialize(m_context->context());

    // Stencils of the same cage at another level: the GPU path fails, the CPU's positions show.
    shown.showSubdivisionPose(otherLevel, edited, cpu);
    failure = agrees("viewport_gpu_subdivision_fallback");
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
    QCOMPARE(view.lastPoseEvaluation(), PoseEvaluation::Uploaded);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, shown.showSubdivisionPose(stencils, {glm::dvec3(0.0)}, cpu));
    view.release();
}

// Stencils that do not fit the shown surface, in a renderer that never evaluated on the
// GPU: the CPU's positions show.
void TestGpuSubdivision::viewportFallsBackToTheCpusPositions()
{
    constexpr QSize kSize = ViewportEdit::kSize;
    const ViewportEdit edit;
    const auto& [cage, scene, stencils, otherLevel, edited, camera, cpu] = edit;

    const auto content = std::make_shared<ShownContent>();
    ViewportRenderer view(content);
    content->setScene(scene);
    ContentPublisher shown(content, ContentOwner::DesignHistory);
    m_context->makeCurrent();
    view.initialize(m_context->context());
    shown.showSubdivisionPose(otherLevel, edited, cpu);
    const std::optional<QString> failure = viewportAgrees(view, camera, kSize, "viewport_fallback_alone", cpu);
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
    QCOMPARE(view.lastPoseEvaluation(), PoseEvaluation::Uploaded);
    view.release();
}

// A viewport renderer released and made again in the same context evaluates on the GPU
// again (names of the first renderer's objects are free to be reused by then).
void TestGpuSubdivision::viewportEvaluatesAgainInTheSameContext()
{
    constexpr QSize kSize = ViewportEdit::kSize;
    const ViewportEdit edit;
    const auto& [cage, scene, stencils, otherLevel, edited, camera, cpu] = edit;

    const auto content = std::make_shared<ShownContent>();
    ViewportRenderer view(content);
    content->setScene(scene);
    ContentPublisher shown(content, ContentOwner::DesignHistory);
    m_context->makeCurrent();
    for (int round = 0; round < 2; ++round) {
        view.initialize(m_context->context());
        shown.showSubdivisionPose(stencils, edited, cpu);
        const std::optional<QString> failure =
            viewportAgrees(view, camera, kSize, QString("viewport_same_context_%1").arg(round), cpu);
        QVERIFY2(!failure, failure ? qPrintable(QString("round %1: %2").arg(round).arg(*failure)) : "");
        QCOMPARE(view.lastPoseEvaluation(), PoseEvaluation::GpuSubdivision);
        view.release();
    }
}

void TestGpuSubdivision::refusesMismatches()
{
    const SubdivisionCage cage = cubeCage();
    const SubdivisionSurface surface(cage, {2, SubdivisionMode::Limit});
    m_renderer->setScene(sceneOf(surface.mesh()));
    GpuSubdivision gpu(m_renderer->gl(), subdivisionStencils(surface));
    std::vector<glm::dvec3> points = cage.positions;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             gpu.evaluate(m_renderer->gpuScene(), 0, std::span(points).first(points.size() - 1)));
    points[3].y = std::nan("");
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, gpu.evaluate(m_renderer->gpuScene(), 0, points));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, gpu.evaluate(m_renderer->gpuScene(), 1, cage.positions));
    m_renderer->setScene(sceneOf(SubdivisionSurface(cage, {1, SubdivisionMode::Limit}).mesh()));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, gpu.evaluate(m_renderer->gpuScene(), 0, cage.positions));
    SubdivisionStencils broken = subdivisionStencils(surface);
    broken.indices.front() = int(cage.vertexCount());
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, GpuSubdivision(m_renderer->gl(), broken));
}

QTEST_MAIN(TestGpuSubdivision)
#include "tst_gpu_subdivision.moc"
