// Stroke scripts that reproduce thesis Figures 8.7 and 8.13 (tests/data/scripts), replayed
// with the designer's brush: the GPU's dynamic rules agree with the exact CPU reference
// on >= 99.9 % of compared pixels for every buffer method, and the static and dynamic
// results differ, only where the last set's strokes are (the figures' bump and notch).
#include "gl_test_context.h"
#include "method_check.h"
#include "replay_check.h"
#include "test_paths.h"

#include "core/catalog/scene_source.h"
#include "core/timeline/frame_chain.h"
#include "core/timeline/stroke_replay.h"
#include "core/timeline/stroke_script.h"

#include <QtTest>

using namespace trimlab;
using namespace trimlab::render;

namespace {

constexpr int kWidth = 200;
constexpr int kHeight = 150;

struct Replay {
    const char* script;
    const char* source;
    Camera camera;
    TrimSettings settings;
    int minimumDiffering; // pixels where static and dynamic must differ
};

Camera cameraAt(const glm::dvec3& eye, const glm::dvec3& target, double fovy)
{
    Camera camera;
    camera.eye = eye;
    camera.target = target;
    camera.fovyDegrees = fovy;
    return camera;
}

std::vector<Replay> replays()
{
    TrimSettings clipped;
    clipped.clip = ClipPlane{true, {0.0, 0.0, -1.0}, 0.0}; // the half behind z = 0: the cut shows the interior
    return {
        {"fig8_7_extended_tip.json", "demo:sphere", cameraAt({0.3, -0.8, 3.4}, {0.0, -0.6, 0.0}, 45.0), clipped, 150},
        {"fig8_13_dent_into_overlap.json", "demo:crossing-loop", cameraAt({-0.6, 1.6, 0.9}, {-0.1, 0.0, -0.1}, 40.0),
         TrimSettings{}, 150},
    };
}

struct Replayed {
    timeline::Timeline timeline;
    DynamicChain chain;
    Camera camera;
};

Replayed replay(const Replay& r)
{
    const LoadedScene loaded = loadScene(r.source);
    const timeline::StrokeScript script =
        timeline::loadStrokeScript(test::testDataPath(std::string("scripts/") + r.script));
    Replayed result{timeline::replayStrokeScript(loaded.scene.objects.front().mesh, script), {}, {}};
    const int last = result.timeline.frameCount() - 1;
    result.chain = timeline::frameChain(result.timeline, last, r.settings.rule);
    result.camera = withDepthRange(r.camera, timeline::chainBounds(result.chain));
    return result;
}

} // namespace

Q_DECLARE_METATYPE(trimlab::render::FragmentMethodKind)

class TestDesignReplays : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void gpuAgreesWithReference_data();
    void gpuAgreesWithReference();
    void staticAndDynamicDifferOnlyAtTheLastSet_data();
    void staticAndDynamicDifferOnlyAtTheLastSet();

private:
    std::unique_ptr<OffscreenGlContext> m_context;
    std::unique_ptr<TrimRenderer> m_renderer;
};

void TestDesignReplays::initTestCase()
{
    TRIMLAB_INIT_GL_CONTEXT(m_context);
    m_renderer = std::make_unique<TrimRenderer>(m_context->context());
}

void TestDesignReplays::gpuAgreesWithReference_data()
{
    QTest::addColumn<int>("replayIndex");
    QTest::addColumn<FragmentMethodKind>("method");
    const std::vector<Replay> all = replays();
    for (int i = 0; i < int(all.size()); ++i)
        for (const MethodInfo& info : fragmentMethods())
            if (info.dynamicRules)
                QTest::newRow(qPrintable(QString("%1: %2").arg(all[std::size_t(i)].script, info.id.data())))
                    << i << info.kind;
}

void TestDesignReplays::gpuAgreesWithReference()
{
    QFETCH(int, replayIndex);
    QFETCH(FragmentMethodKind, method);
    const Replay r = replays()[std::size_t(replayIndex)];
    const Replayed replayed = replay(r);
    test::MethodCase testCase{QString::fromLatin1(r.script), replayed.camera, r.settings, {}, kWidth, kHeight};
    testCase.parameters.k = 32;
    QString summary;
    if (const auto failure =
            test::checkDynamicChainAgainstReference(*m_renderer, method, replayed.chain, testCase, &summary))
        QFAIL(qPrintable(*failure));
    qInfo("%s", qPrintable(summary));
}

void TestDesignReplays::staticAndDynamicDifferOnlyAtTheLastSet_data()
{
    QTest::addColumn<int>("replayIndex");
    const std::vector<Replay> all = replays();
    for (int i = 0; i < int(all.size()); ++i)
        QTest::newRow(all[std::size_t(i)].script) << i;
}

void TestDesignReplays::staticAndDynamicDifferOnlyAtTheLastSet()
{
    QFETCH(int, replayIndex);
    const Replay r = replays()[std::size_t(replayIndex)];
    const Replayed replayed = replay(r);
    const test::StaticDynamicDifference difference =
        test::compareStaticAndDynamic(replayed.timeline, replayed.chain, replayed.camera, kWidth, kHeight, r.settings);
    const int differing = difference.differing;
    const int elsewhere = difference.elsewhere;
    qInfo("%d pixels differ between the static and the dynamic rule, %d of them away from the last set", differing,
          elsewhere);
    QVERIFY2(differing >= r.minimumDiffering, qPrintable(QString("only %1 pixels differ").arg(differing)));
    QCOMPARE(elsewhere, 0);
}

QTEST_MAIN(TestDesignReplays)
#include "tst_design_replays.moc"
