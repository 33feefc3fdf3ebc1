// The render layer ends the CPU's wide-vector state where driver calls hand back to CPU work
// (render/gl/wide_vector_state.h). Mesa never leaves that state in use, so each check puts
// it in use itself (a 256-bit register write, as NVIDIA's driver leaves it) right before the
// call under test and asks the CPU (XGETBV 1) whether the call ended it. Skipped on CPUs
// that cannot say (no AVX or no XGETBV 1).
#include "render/gl/wide_vector_state.h"
#include "render/gl/offscreen_gl_context.h"
#include "gl_test_context.h"
#include "render/frame/gpu_scene.h"
#include "render/trim_renderer.h"

#include "core/catalog/demo_scenes.h"
#include "core/view/camera.h"

#include <QtTest>

using namespace trimlab;
using namespace trimlab::render;

namespace {

// A 256-bit write, as the driver's copy routines make (x86 with AVX only: the callers skip
// elsewhere, where wideVectorStateInUse() has no answer).
void useWideVectorState()
{
#if defined(__x86_64__) || defined(__i386__)
    asm volatile("vpcmpeqd %%ymm0, %%ymm0, %%ymm0" ::: "xmm0");
#endif
}

// Whether `call` ends the state that was in use when it began.
template <class Call>
bool endsWideVectorState(Call&& call)
{
    useWideVectorState();
    if (wideVectorStateInUse() != true)
        return false; // the write above did not register: the check would prove nothing
    call();
    return wideVectorStateInUse() == false;
}

} // namespace

class TestWideVectorState : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void leaveEndsTheStateAndScopesEndItTwice();
    void contextAndRendererCallsEndTheState();

private:
    std::unique_ptr<OffscreenGlContext> m_gl;
};

void TestWideVectorState::initTestCase()
{
    if (!wideVectorStateInUse())
        QSKIP("this CPU cannot report its wide-vector state (no AVX or no XGETBV 1)");
    TRIMLAB_INIT_GL_CONTEXT(m_gl);
}

void TestWideVectorState::leaveEndsTheStateAndScopesEndItTwice()
{
    useWideVectorState();
    QCOMPARE(wideVectorStateInUse(), std::optional<bool>(true));
    leaveWideVectorState();
    QCOMPARE(wideVectorStateInUse(), std::optional<bool>(false));

    useWideVectorState();
    {
        const WideVectorStateScope scope; // on entry: the function's own CPU work runs clean
        QCOMPARE(wideVectorStateInUse(), std::optional<bool>(false));
        useWideVectorState(); // a driver call inside the function
    }
    QCOMPARE(wideVectorStateInUse(), std::optional<bool>(false)); // and on exit, for the caller
}

void TestWideVectorState::contextAndRendererCallsEndTheState()
{
    const std::optional<Scene> scene = makeDemoScene("pushed-sphere");
    QVERIFY(scene);
    TrimRenderer renderer(m_gl->context());
    const Camera camera = fitCamera(scene->worldBounds(), 4.0 / 3.0);
    const TrimSettings settings;
    QVERIFY(endsWideVectorState([&] { m_gl->makeCurrent(); }));
    QVERIFY(endsWideVectorState([&] { renderer.setScene(*scene); }));
    QVERIFY(endsWideVectorState([&] { renderer.render(camera, settings, 64, 48); }));
    QVERIFY(endsWideVectorState([&] { (void)renderer.readTrimImage(); }));
    QVERIFY(endsWideVectorState([&] { (void)renderer.readColor(); }));
    const std::vector<glm::vec3> positions = renderer.gpuScene().readPositions(0);
    QVERIFY(!positions.empty());
    QVERIFY(endsWideVectorState([&] { renderer.gpuScene().updatePositions(0, positions); }));
    QVERIFY(endsWideVectorState([&] { (void)renderer.gpuScene().readNormals(0); }));
    QVERIFY(renderer.lastStats().counts.fragmentsStored > 0); // the frames were real
    // The viewport's pipelined frames: issued, then their results collected or waited for.
    renderer.setPipelined(true);
    QVERIFY(endsWideVectorState([&] { renderer.render(camera, settings, 64, 48); }));
    QVERIFY(endsWideVectorState([&] { (void)renderer.collectFrames(); }));
    renderer.render(camera, settings, 64, 48);
    QVERIFY(endsWideVectorState([&] { renderer.finishFrames(); }));
    QVERIFY(!renderer.framesPending());
}

QTEST_MAIN(TestWideVectorState)
#include "tst_wide_vector_state.moc"
