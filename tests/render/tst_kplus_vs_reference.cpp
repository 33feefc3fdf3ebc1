// The k+-buffer against the exact CPU reference: demo scenes and real meshes from
// ../shared/data, several cameras, clip planes and rules. Per pixel, the shown primitive,
// object and facing and the winding index at the span start must agree on >= 99.9 % of
// the covered pixels; pixels a float rasteriser may legitimately decide differently are
// excluded by definitions taken from the reference (tests/support/trim_comparison.h),
// counted, and bounded. Failures write actual/expected/diff images.
#include "gl_test_context.h"
#include "image_artifacts.h"
#include "test_paths.h"
#include "trim_comparison.h"
#include "trim_renderer.h"

#include "scene/scene_source.h"
#include "trim/reference_renderer.h"

#include <glm/geometric.hpp>

#include <QtTest>

#include <map>

using namespace trimlab;
using namespace trimlab::render;

namespace {

constexpr int kWidth = 256;
constexpr int kHeight = 192;
constexpr double kRequiredAgreement = 0.999;
// Excluded pixels lie on triangle edges, silhouettes or near-ties in depth; on these
// scenes they are a few percent of the covered pixels at most. A renderer that is wrong
// everywhere cannot hide behind them.
constexpr double kMaxExcludedFraction = 0.05;

struct Case {
    std::string source;
    glm::dvec3 viewDirection{-0.35, -0.45, -1.0};
    std::optional<glm::dvec3> eye; // when set: the camera sits here looking at the centre
    ClipPlane clip;
    std::optional<StaticRule> rule; // nullopt: trimming off
    int k = 16;
    double zoom = 1.0; // < 1 moves the fitted camera closer (thin meshes cover few pixels)
};

Camera cameraFor(const Case& c, const Bounds& bounds)
{
    Camera camera = fitCamera(bounds, double(kWidth) / kHeight, c.viewDirection);
    camera.eye = camera.target + (camera.eye - camera.target) * c.zoom;
    camera = withDepthRange(camera, bounds);
    if (c.eye) {
        camera.eye = *c.eye;
        camera.target = bounds.center() + glm::dvec3(0.0, 0.0, -0.01);
        camera.fovyDegrees = 70.0;
        camera = withDepthRange(camera, bounds);
    }
    return camera;
}

// A clip plane through the scene centre with the given normal (keeping n·(x−c) >= 0).
ClipPlane planeThroughCenter(const std::string& source, glm::dvec3 normal, double shift = 0.0)
{
    static std::map<std::string, Bounds> boundsCache;
    if (!boundsCache.count(source))
        boundsCache[source] = loadScene(source).scene.worldBounds();
    const Bounds& b = boundsCache[source];
    normal = glm::normalize(normal);
    return ClipPlane{true, normal, -glm::dot(normal, b.center()) + shift * b.radius()};
}

std::string shared(const std::string& relative)
{
    return test::sharedDataPath(relative).string();
}

} // namespace

Q_DECLARE_METATYPE(Case)

class TestKPlusVsReference : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void agreesWithReference_data();
    void agreesWithReference();

private:
    std::unique_ptr<OffscreenGlContext> m_context;
    std::unique_ptr<TrimRenderer> m_renderer;
    std::map<std::string, LoadedScene> m_scenes;
};

void TestKPlusVsReference::initTestCase()
{
    TRIMLAB_INIT_GL_CONTEXT(m_context);
    m_renderer = std::make_unique<TrimRenderer>(m_context->context());
}

void TestKPlusVsReference::agreesWithReference_data()
{
    QTest::addColumn<Case>("testCase");
    const std::string pushed = "demo:pushed-sphere";
    const std::string loop = "demo:crossing-loop";
    const std::string man = shared("selfintersect/cgal-man.off.gz");
    const std::string spot = shared("static/odedstein-spot.obj.gz");
    const auto ab = StaticRule::AlternatingBorder;
    const auto pos = StaticRule::PositiveIndex;
    const auto par = StaticRule::Parity;

    QTest::newRow("pushed-sphere alternating") << Case{pushed, {-0.35, -0.45, -1.0}, {}, {}, ab};
    QTest::newRow("pushed-sphere positive") << Case{pushed, {-0.35, -0.45, -1.0}, {}, {}, pos};
    QTest::newRow("pushed-sphere parity") << Case{pushed, {-0.35, -0.45, -1.0}, {}, {}, par};
    QTest::newRow("pushed-sphere untrimmed") << Case{pushed, {-0.35, -0.45, -1.0}, {}, {}, std::nullopt};
    QTest::newRow("pushed-sphere from below, clipped")
        << Case{pushed, {0.2, 1.0, -0.3}, {}, planeThroughCenter(pushed, {0.0, 0.0, -1.0}), ab};
    QTest::newRow("pushed-sphere tilted plane")
        << Case{pushed, {-0.35, -0.45, -1.0}, {}, planeThroughCenter(pushed, {0.4, -0.3, -1.0}, 0.1), ab};
    QTest::newRow("pushed-sphere plane facing the camera")
        << Case{pushed, {-0.35, -0.45, -1.0}, {}, planeThroughCenter(pushed, {0.2, 0.3, 1.0}), pos};
    QTest::newRow("pushed-sphere camera inside")
        << Case{pushed, {}, glm::dvec3(0.45, 0.2, 0.35), {}, ab};
    QTest::newRow("crossing-loop alternating") << Case{loop, {0.1, -0.8, -1.0}, {}, {}, ab};
    QTest::newRow("crossing-loop positive, clipped")
        << Case{loop, {0.1, -0.8, -1.0}, {}, planeThroughCenter(loop, {0.0, 1.0, -0.2}), pos};
    QTest::newRow("cgal-man alternating, clipped")
        << Case{man, {-0.35, -0.45, -1.0}, {}, planeThroughCenter(man, {0.0, 0.0, -1.0}), ab, 24, 0.55};
    QTest::newRow("cgal-man positive, side view")
        << Case{man, {1.0, -0.2, 0.1}, {}, planeThroughCenter(man, {-1.0, 0.1, 0.0}, -0.05), pos, 24, 0.6};
    QTest::newRow("cgal-man parity") << Case{man, {0.3, 0.4, -1.0}, {}, {}, par, 24, 0.6};
    QTest::newRow("spot alternating, clipped")
        << Case{spot, {-0.35, -0.45, -1.0}, {}, planeThroughCenter(spot, {0.3, 0.0, -1.0}), ab};
    QTest::newRow("spot camera inside, positive")
        << Case{spot, {}, glm::dvec3(0.0, 0.1, 0.05), {}, pos};
}

void TestKPlusVsReference::agreesWithReference()
{
    QFETCH(Case, testCase);
    if (!testCase.source.starts_with("demo:") && !std::filesystem::exists(testCase.source))
        QSKIP(qPrintable(QString::fromStdString("shared data missing: " + testCase.source)));
    if (!m_scenes.count(testCase.source))
        m_scenes.emplace(testCase.source, loadScene(testCase.source));
    const LoadedScene& loaded = m_scenes.at(testCase.source);
    QVERIFY2(loaded.trimmable(), loaded.trimUnavailableReason().c_str());

    TrimSettings settings;
    settings.trimEnabled = testCase.rule.has_value();
    settings.rule = testCase.rule.value_or(StaticRule::AlternatingBorder);
    settings.clip = testCase.clip;
    const Camera camera = cameraFor(testCase, loaded.scene.worldBounds());

    m_renderer->setScene(loaded.scene);
    m_renderer->setK(testCase.k);
    m_renderer->render(camera, settings, kWidth, kHeight);
    const TrimImage gpu = m_renderer->readTrimImage();
    const ReferenceResult reference = ReferenceRenderer(loaded.scene).render(camera, kWidth, kHeight, settings);

    const test::TrimComparison comparison = test::compareTrimImages(gpu, reference.trim, reference.diagnostics);
    qInfo("%s: %s; %.2f ms wall, %llu unresolved", QTest::currentDataTag(), qPrintable(comparison.summary()),
          m_renderer->lastStats().wallMilliseconds,
          static_cast<unsigned long long>(m_renderer->lastStats().counts.unresolvedPixels));
    QVERIFY2(comparison.coveredPixels > kWidth * kHeight / 20, "the scene barely covers the image: a useless case");
    const bool ok = comparison.agreement() >= kRequiredAgreement && comparison.excludedFraction() <= kMaxExcludedFraction;
    if (!ok) {
        const QString name = QString(QTest::currentDataTag()).replace(' ', '_').replace(',', "");
        const QString files = test::writeComparisonArtifacts(name, test::trimImageToPicture(gpu),
                                                             test::trimImageToPicture(reference.trim),
                                                             comparison.disagreementMask);
        QFAIL(qPrintable(comparison.summary() + "; " + files));
    }
}

QTEST_MAIN(TestKPlusVsReference)
#include "tst_kplus_vs_reference.moc"
