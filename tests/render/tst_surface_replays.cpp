// Thesis Fig. 8.13 on an editable NURBS sphere: control-point edits push the north pole
// through the sphere and out below the south side. The last frame, rendered under the
// static rule and under the dynamic rules (confluent, constructive subtractive) with
// every buffer method that runs dynamic rules, agrees with the exact CPU reference on
// >= 99.9 % of compared pixels; the static rule (parity) shows the pushed tip as a bump
// where the dynamic rules carve a hole, and the two differ only on the moved triangles.
// A subdivision surface's control-point edit is checked against the reference as well.
#include "gl_test_context.h"
#include "image_artifacts.h"
#include "method_check.h"
#include "replay_check.h"

#include "core/catalog/fig8_13_history.h"
#include "core/timeline/frame_chain.h"

#include <QtTest>

using namespace trimlab;
using namespace trimlab::render;

namespace {

constexpr int kWidth = 200;
constexpr int kHeight = 150;
/// The static rule of the base mesh and of the static rendering: parity classifies the
/// tip's index −1 as interior (the unintuitive bump), the dynamic rules as carved.
constexpr StaticRule kStaticRule = StaticRule::Parity;

struct SurfaceCase {
    const char* name;
    int history;          // 0: fig8_13NurbsHistory, 1: subdivisionPushHistory
    DynamicRule pushRule; // the rule of the last set
};

std::vector<SurfaceCase> surfaceCases()
{
    return {{"nurbs-fig8.13-confluent", 0, DynamicRule::Confluent},
            {"nurbs-fig8.13-subtractive", 0, DynamicRule::ConstructiveSubtractive},
            {"subdivision-push-confluent", 1, DynamicRule::Confluent}};
}

struct Prepared {
    timeline::Timeline history;
    DynamicChain chain;
    Camera camera;
    TrimSettings settings;
};

Prepared prepare(const SurfaceCase& c)
{
    Prepared p{c.history == 0 ? fig8_13NurbsHistory(DynamicRule::Confluent, c.pushRule)
                              : subdivisionPushHistory(c.pushRule),
               {},
               {},
               {}};
    p.settings.rule = kStaticRule;
    const int last = p.history.frameCount() - 1;
    p.chain = timeline::frameChain(p.history, last, kStaticRule);
    // NURBS: below and to the side of the sphere, looking up at the south pole where the
    // tip comes out. Subdivision: above the pushed corner.
    Camera camera;
    camera.eye = c.history == 0 ? glm::dvec3(1.1, -3.4, 1.6) : glm::dvec3(1.6, 1.9, 2.2);
    camera.target = c.history == 0 ? glm::dvec3(0.0, -0.6, 0.0) : glm::dvec3(0.0, -0.2, 0.0);
    camera.fovyDegrees = 40.0;
    p.camera = withDepthRange(camera, timeline::chainBounds(p.chain));
    return p;
}

} // namespace

Q_DECLARE_METATYPE(trimlab::render::FragmentMethodKind)

class TestSurfaceReplays : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void dynamicRulesAgreeWithReference_data();
    void dynamicRulesAgreeWithReference();
    void staticRuleAgreesWithReference_data();
    void staticRuleAgreesWithReference();
    void staticShowsABumpWhereDynamicCarvesAHole();

private:
    std::unique_ptr<OffscreenGlContext> m_context;
    std::unique_ptr<TrimRenderer> m_renderer;
};

void TestSurfaceReplays::initTestCase()
{
    TRIMLAB_INIT_GL_CONTEXT(m_context);
    m_renderer = std::make_unique<TrimRenderer>(m_context->context());
}

void TestSurfaceReplays::dynamicRulesAgreeWithReference_data()
{
    QTest::addColumn<int>("caseIndex");
    QTest::addColumn<FragmentMethodKind>("method");
    const std::vector<SurfaceCase> all = surfaceCases();
    for (int i = 0; i < int(all.size()); ++i) {
        for (const MethodInfo& info : fragmentMethods()) {
            if (!info.dynamicRules)
                continue;
            QTest::newRow(qPrintable(QString("%1: %2").arg(all[std::size_t(i)].name, info.id.data())))
                << i << info.kind;
            if (all[std::size_t(i)].history == 1)
                break; // one method is enough for the subdivision surface
        }
    }
}

void TestSurfaceReplays::dynamicRulesAgreeWithReference()
{
    QFETCH(int, caseIndex);
    QFETCH(FragmentMethodKind, method);
    const SurfaceCase c = surfaceCases()[std::size_t(caseIndex)];
    const Prepared p = prepare(c);
    test::MethodCase testCase{QString::fromLatin1(c.name), p.camera, p.settings, {}, kWidth, kHeight};
    testCase.parameters.k = 32;
    QString summary;
    if (const auto failure = test::checkDynamicChainAgainstReference(*m_renderer, method, p.chain, testCase, &summary))
        QFAIL(qPrintable(*failure));
    qInfo("%s", qPrintable(summary));
}

void TestSurfaceReplays::staticRuleAgreesWithReference_data()
{
    QTest::addColumn<FragmentMethodKind>("method");
    for (const MethodInfo& info : fragmentMethods())
        if (info.dynamicRules)
            QTest::newRow(info.id.data()) << info.kind;
}

void TestSurfaceReplays::staticRuleAgreesWithReference()
{
    QFETCH(FragmentMethodKind, method);
    const Prepared p = prepare(surfaceCases().front());
    const Scene current = timeline::frameScene(p.history, p.history.frameCount() - 1);
    test::MethodCase testCase{QStringLiteral("nurbs-fig8.13-static"), p.camera, p.settings, {}, kWidth, kHeight};
    testCase.parameters.k = 32;
    m_renderer->setScene(current);
    const ReferenceRenderer referenceRenderer(current);
    const ReferenceResult reference = referenceRenderer.render(testCase.camera, kWidth, kHeight, testCase.settings);
    QString summary;
    const auto failure =
        test::checkMethodAgainstReference(*m_renderer, method, testCase, referenceRenderer, reference, &summary);
    qInfo("%s", qPrintable(summary));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
}

void TestSurfaceReplays::staticShowsABumpWhereDynamicCarvesAHole()
{
    for (const SurfaceCase& c : surfaceCases()) {
        if (c.history != 0)
            continue;
        const Prepared p = prepare(c);
        // deeper: the dynamic rule shows something farther away, or nothing: a hole.
        const auto [dynamic, staticImage, differing, elsewhere, deeper] =
            test::compareStaticAndDynamic(p.history, p.chain, p.camera, kWidth, kHeight, p.settings);
        const QString counts = QString("%1: %2 pixels differ between the static and the dynamic rule, %3 of them "
                                       "away from the pushed part, %4 show a hole under the dynamic rule where the "
                                       "static one shows the bump")
                                   .arg(c.name)
                                   .arg(differing)
                                   .arg(elsewhere)
                                   .arg(deeper);
        qInfo("%s", qPrintable(counts));
        // Every differing pixel: a bump (static) against a hole (dynamic), on the pushed part.
        if (differing < 300 || elsewhere != 0 || deeper != differing) {
            QImage mask(kWidth, kHeight, QImage::Format_Grayscale8);
            for (int y = 0; y < kHeight; ++y)
                for (int x = 0; x < kWidth; ++x)
                    mask.scanLine(y)[x] = dynamic.at(x, y).primitiveId != staticImage.at(x, y).primitiveId ? 255 : 0;
            const QString note = test::writeComparisonArtifacts(QString(c.name) + "-dynamic-vs-static",
                                                                test::trimImageToPicture(dynamic),
                                                                test::trimImageToPicture(staticImage), mask);
            QFAIL(qPrintable(counts + "; expected >= 300, 0 away, all holes; " + note));
        }
    }
}

QTEST_MAIN(TestSurfaceReplays)
#include "tst_surface_replays.moc"
