// Pipelined frames (render/frame/frame_results.h): the viewport's frame path never makes
// the CPU wait for the GPU — no query result, counter or image is read back in the frame
// that produced it — and the results still arrive, later, equal to those of a frame that
// waited. The waits are counted by the GL wrapper every render call goes through
// (render/gl/gl_functions.h), so a blocking read put back into the frame path (the time
// query read with GL_QUERY_RESULT, the counters read with glGetBufferSubData) fails here.
// The methods that read back mid-frame by design are the ones MethodInfo names.
#include "gl_test_context.h"
#include "method_check.h"

#include "render/content_publisher.h"
#include "render/gl/gl_functions.h"
#include "render/viewport_renderer.h"

#include "core/catalog/demo_scenes.h"
#include "core/catalog/fig8_13_history.h"
#include "core/timeline/frame_chain.h"
#include "core/trim/dynamic_chain.h"
#include "core/trim/reference_renderer.h"

#include <QElapsedTimer>
#include <QThread>
#include <QtTest>

#include <cmath>
#include <memory>
#include <optional>

using namespace trimlab;
using namespace trimlab::render;

namespace {

constexpr QSize kSize(128, 96);
constexpr int kArrivalTimeoutMs = 20000;

/// Collects results as the viewport's event loop does, until none is pending; false on
/// timeout.
bool collectUntilArrived(ViewportRenderer& view)
{
    QElapsedTimer clock;
    clock.start();
    while (view.framesPending()) {
        (void)view.collectFrames();
        if (clock.elapsed() > kArrivalTimeoutMs)
            return false;
        if (view.framesPending())
            QThread::usleep(200);
    }
    return true;
}

/// `base` turned by `degrees` about the vertical axis through its target.
Camera orbited(const Camera& base, double degrees)
{
    Camera camera = base;
    const glm::dvec3 offset = base.eye - base.target;
    const double angle = glm::radians(degrees);
    camera.eye = base.target + glm::dvec3(offset.x * std::cos(angle) + offset.z * std::sin(angle), offset.y,
                                          -offset.x * std::sin(angle) + offset.z * std::cos(angle));
    return camera;
}

bool sameCounts(const FrameCounts& a, const FrameCounts& b)
{
    return a.fragmentsInSpan == b.fragmentsInSpan && a.fragmentsStored == b.fragmentsStored &&
           a.fragmentsLost == b.fragmentsLost && a.overflowPixels == b.overflowPixels &&
           a.unresolvedPixels == b.unresolvedPixels && a.capPixels == b.capPixels;
}

} // namespace

Q_DECLARE_METATYPE(trimlab::render::FragmentMethodKind)

class TestPipelinedFrames : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void viewportFramesNeverWaitForTheGpu_data();
    void viewportFramesNeverWaitForTheGpu();
    void dynamicFramesNeverWaitForTheGpu();
    void aFrameThatWaitsIsCounted();
    void midFrameReadbacksAreTheMethodsNamed();

private:
    std::unique_ptr<OffscreenGlContext> m_gl;
};

void TestPipelinedFrames::initTestCase()
{
    TRIMLAB_INIT_GL_CONTEXT(m_gl);
}

void TestPipelinedFrames::viewportFramesNeverWaitForTheGpu_data()
{
    QTest::addColumn<FragmentMethodKind>("method");
    // The methods without a mid-frame readback that keep every fragment of this scene
    // (the two-pass method keeps the first layer only: lost fragments ask for a readback).
    for (const FragmentMethodKind method :
         {FragmentMethodKind::KPlusArray, FragmentMethodKind::KPlusHeap, FragmentMethodKind::ABufferFixed})
        QTest::newRow(methodInfo(method).id.data()) << method;
}

// Frames one at a time (painted, then collected from the event loop) and three in a row
// (the GPU behind by two): no counted wait from the first render() to the last result,
// every frame's numbers arrive, and the last one's equal a waiting frame's and its image
// agrees with the exact reference.
void TestPipelinedFrames::viewportFramesNeverWaitForTheGpu()
{
    QFETCH(FragmentMethodKind, method);
    auto scene = std::make_shared<const Scene>(*makeDemoScene("pushed-sphere"));
    const Camera base = fitCamera(scene->worldBounds(), double(kSize.width()) / kSize.height());
    const auto content = std::make_shared<ShownContent>();
    content->setScene(scene);
    ViewportRenderer view(content);
    view.setMethod(method);
    m_gl->makeCurrent();
    view.initialize(m_gl->context());
    QVERIFY(view.renderer().pipelined());
    const auto ignore = [](const std::string&) {};
    QVERIFY(view.render(base, kSize, 0, ignore)); // shaders and storage: not part of the frame path
    view.finishFrames();
    QVERIFY(view.lastFrame());
    QCOMPARE(view.lastFrame()->stats.counts.fragmentsLost, std::uint64_t(0)); // no overflow readback

    GlFunctions& gl = currentGlFunctions();
    const std::uint64_t before = gl.gpuWaits();
    for (int frame = 1; frame <= 3; ++frame) {
        QVERIFY(view.render(orbited(base, 10.0 * frame), kSize, 0, ignore));
        QCOMPARE(gl.gpuWaits(), before);
        QVERIFY(collectUntilArrived(view));
        QCOMPARE(view.lastFrame()->stats.serial, view.renderer().lastIssuedFrame());
    }
    for (int frame = 4; frame <= 6; ++frame)
        QVERIFY(view.render(orbited(base, 10.0 * frame), kSize, 0, ignore));
    QCOMPARE(gl.gpuWaits(), before);
    QVERIFY(collectUntilArrived(view));
    QCOMPARE(gl.gpuWaits(), before);

    const ViewFrame shown = *view.lastFrame();
    QCOMPARE(shown.stats.serial, view.renderer().lastIssuedFrame());
    QVERIFY(shown.camera == orbited(base, 60.0));
    QVERIFY(shown.stats.counts.fragmentsInSpan > 0);
    QVERIFY(shown.stats.wallMilliseconds >= shown.stats.issueMilliseconds);
    const MethodMeasurement waited = view.measure(method, 1, shown.camera, kSize);
    QVERIFY2(sameCounts(shown.stats.counts, waited.lastStats.counts),
             qPrintable(QStringLiteral("pipelined %1 fragments, %2 stored; waiting %3, %4")
                            .arg(shown.stats.counts.fragmentsInSpan)
                            .arg(shown.stats.counts.fragmentsStored)
                            .arg(waited.lastStats.counts.fragmentsInSpan)
                            .arg(waited.lastStats.counts.fragmentsStored)));
    QVERIFY(view.renderer().pipelined()); // measure() waits only for its own frames

    QVERIFY(view.render(shown.camera, kSize, 0, ignore));
    view.finishFrames();
    const ReferenceResult reference =
        ReferenceRenderer(*scene).render(shown.camera, kSize.width(), kSize.height(), TrimSettings{});
    const test::MethodCase testCase{QStringLiteral("pipelined_%1").arg(methodInfo(method).id.data()),
                                    shown.camera,
                                    TrimSettings{},
                                    view.methodParameters(),
                                    kSize.width(),
                                    kSize.height()};
    const std::optional<QString> failure = test::checkFrameAgainstReference(view.renderer(), testCase, reference, {});
    QVERIFY2(!failure, qPrintable(failure.value_or(QString())));
    view.release();
}

// Under the dynamic rules a frame is several passes (each earlier level characterized,
// then the shown one): none waits either, and only the shown pass is timed.
void TestPipelinedFrames::dynamicFramesNeverWaitForTheGpu()
{
    const timeline::Timeline history = fig8_13NurbsHistory();
    const int last = history.frameCount() - 1;
    auto chain = std::make_shared<const DynamicChain>(timeline::frameChain(history, last, StaticRule::Parity));
    auto scene = std::make_shared<const Scene>(timeline::frameScene(history, last));
    const Camera base = fitCamera(timeline::chainBounds(*chain), double(kSize.width()) / kSize.height());
    TrimSettings settings;
    settings.rule = StaticRule::Parity;
    const auto content = std::make_shared<ShownContent>();
    content->setScene(scene);
    ViewportRenderer view(content);
    view.setTrimSettings(settings);
    view.setMethod(FragmentMethodKind::KPlusArray);
    ContentPublisher(content, ContentOwner::DesignHistory).showChain(chain);
    m_gl->makeCurrent();
    view.initialize(m_gl->context());
    const auto ignore = [](const std::string&) {};
    QVERIFY(view.render(base, kSize, 0, ignore));
    view.finishFrames();
    QVERIFY(view.lastDynamicStats().has_value());
    QVERIFY(view.lastDynamicStats()->levels > 1);

    GlFunctions& gl = currentGlFunctions();
    const std::uint64_t before = gl.gpuWaits();
    const std::uint64_t issuedBefore = view.renderer().lastIssuedFrame();
    QVERIFY(view.render(orbited(base, 15.0), kSize, 0, ignore)); // a new view: every level characterized again
    QCOMPARE(gl.gpuWaits(), before);
    QVERIFY(view.lastDynamicStats()->characterizedLevels > 0);
    QVERIFY(collectUntilArrived(view));
    QCOMPARE(gl.gpuWaits(), before);
    QVERIFY(view.renderer().lastIssuedFrame() > issuedBefore + 1); // the characterization passes
    QCOMPARE(view.lastFrame()->stats.serial, view.renderer().lastIssuedFrame());
    QVERIFY(view.lastFrame()->stats.counts.fragmentsInSpan > 0);
    view.release();
}

// The counter sees what the frame path must not do: a renderer that waits (the batch
// verbs' and the benchmark's) reads its time query and counters in the frame.
void TestPipelinedFrames::aFrameThatWaitsIsCounted()
{
    m_gl->makeCurrent();
    const std::optional<Scene> scene = makeDemoScene("pushed-sphere");
    QVERIFY(scene);
    TrimRenderer renderer(m_gl->context());
    QVERIFY(!renderer.pipelined());
    renderer.setScene(*scene);
    const Camera camera = fitCamera(scene->worldBounds(), double(kSize.width()) / kSize.height());
    renderer.render(camera, TrimSettings{}, kSize.width(), kSize.height());
    GlFunctions& gl = currentGlFunctions();
    const std::uint64_t before = gl.gpuWaits();
    renderer.render(camera, TrimSettings{}, kSize.width(), kSize.height());
    QVERIFY(gl.gpuWaits() > before);
    QCOMPARE(renderer.lastStats().serial, renderer.lastIssuedFrame());
    QVERIFY(!renderer.framesPending());

    GlQuery query(gl);
    gl.glBeginQuery(GL_TIME_ELAPSED, query.id());
    gl.glEndQuery(GL_TIME_ELAPSED);
    const std::uint64_t beforeRead = gl.gpuWaits();
    GLuint64 elapsed = 0;
    gl.glGetQueryObjectui64v(query.id(), GL_QUERY_RESULT, &elapsed);
    QCOMPARE(gl.gpuWaits(), beforeRead + 1);
    QVERIFY(gl.tryQueryResult(query.id(), elapsed)); // delivered now: read without a wait
    QCOMPARE(gl.gpuWaits(), beforeRead + 1);
}

// Every method on the viewport's pipelined path: those that read a count back mid-frame
// wait, as MethodInfo::waitsMidFrame says, and no other does.
void TestPipelinedFrames::midFrameReadbacksAreTheMethodsNamed()
{
    m_gl->makeCurrent();
    auto scene = std::make_shared<const Scene>(*makeDemoScene("pushed-sphere"));
    const Camera camera = fitCamera(scene->worldBounds(), double(kSize.width()) / kSize.height());
    const auto content = std::make_shared<ShownContent>();
    content->setScene(scene);
    ViewportRenderer view(content);
    view.initialize(m_gl->context());
    GlFunctions& gl = currentGlFunctions();
    const auto ignore = [](const std::string&) {};
    for (const MethodInfo& info : fragmentMethods()) {
        view.setMethod(info.kind);
        QVERIFY(view.render(camera, kSize, 0, ignore)); // storage and shaders
        view.finishFrames();
        QCOMPARE(view.lastFrame()->stats.method, info.kind);
        const std::uint64_t before = gl.gpuWaits();
        QVERIFY(view.render(orbited(camera, 20.0), kSize, 0, ignore));
        const bool waited = gl.gpuWaits() > before;
        QVERIFY2(waited == info.waitsMidFrame, qPrintable(QStringLiteral("%1 %2 mid-frame, MethodInfo says it %3")
                                                              .arg(info.id.data(), waited ? "waited" : "did not wait",
                                                                   info.waitsMidFrame ? "does" : "does not")));
        QVERIFY(collectUntilArrived(view));
    }
    view.release();
}

QTEST_MAIN(TestPipelinedFrames)
#include "tst_pipelined_frames.moc"
