// Every multi-fragment method against the exact CPU reference on the demo scenes and on
// real meshes from ../shared/data: several cameras (also inside the solid), view-aligned,
// tilted and camera-facing clip planes, all rules and no trimming. Per pixel, the shown
// primitive, object and facing and the winding index at the span start must agree on
// >= 99.9 % of the compared pixels (tests/support/method_check.h).
#include "gl_test_context.h"
#include "method_check.h"
#include "test_paths.h"

#include "core/catalog/scene_source.h"

#include <glm/geometric.hpp>

#include <QtTest>

#include <map>

using namespace trimlab;
using namespace trimlab::render;

namespace {

constexpr int kWidth = 256;
constexpr int kHeight = 192;

struct MeshCase {
    std::string source;
    glm::dvec3 viewDirection{-0.35, -0.45, -1.0};
    std::optional<glm::dvec3> eye;  // when set: the camera sits here looking at the centre
    glm::dvec3 clipNormal{0.0};     // zero: no clip plane; else a plane through the centre
    double clipShift = 0.0;         // in bounding radii along the normal
    std::optional<StaticRule> rule; // nullopt: trimming off
    int k = 16;
    double zoom = 1.0; // < 1 moves the fitted camera closer (thin meshes cover few pixels)
};

Camera cameraFor(const MeshCase& c, const Bounds& bounds)
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

TrimSettings settingsFor(const MeshCase& c, const Bounds& bounds)
{
    TrimSettings settings;
    settings.trimEnabled = c.rule.has_value();
    settings.rule = c.rule.value_or(StaticRule::AlternatingBorder);
    if (glm::length(c.clipNormal) > 0.0) {
        const glm::dvec3 n = glm::normalize(c.clipNormal);
        settings.clip = ClipPlane{true, n, -glm::dot(n, bounds.center()) + c.clipShift * bounds.radius()};
    }
    return settings;
}

std::string shared(const std::string& relative)
{
    return test::sharedDataPath(relative).string();
}

std::vector<std::pair<const char*, MeshCase>> meshCases()
{
    const std::string pushed = "demo:pushed-sphere";
    const std::string loop = "demo:crossing-loop";
    const std::string man = shared("selfintersect/cgal-man.off.gz");
    const std::string spot = shared("static/odedstein-spot.obj.gz");
    const auto ab = StaticRule::AlternatingBorder;
    const auto pos = StaticRule::PositiveIndex;
    const auto par = StaticRule::Parity;
    const glm::dvec3 front{-0.35, -0.45, -1.0};
    return {
        {"pushed-sphere alternating", {pushed, front, {}, {}, 0.0, ab}},
        {"pushed-sphere positive", {pushed, front, {}, {}, 0.0, pos}},
        {"pushed-sphere parity", {pushed, front, {}, {}, 0.0, par}},
        {"pushed-sphere untrimmed", {pushed, front, {}, {}, 0.0, std::nullopt}},
        {"pushed-sphere from below, clipped", {pushed, {0.2, 1.0, -0.3}, {}, {0.0, 0.0, -1.0}, 0.0, ab}},
        {"pushed-sphere tilted plane", {pushed, front, {}, {0.4, -0.3, -1.0}, 0.1, ab}},
        {"pushed-sphere plane facing the camera", {pushed, front, {}, {0.2, 0.3, 1.0}, 0.0, pos}},
        {"pushed-sphere camera inside", {pushed, {}, glm::dvec3(0.45, 0.2, 0.35), {}, 0.0, ab}},
        {"crossing-loop alternating", {loop, {0.1, -0.8, -1.0}, {}, {}, 0.0, ab}},
        {"crossing-loop positive, clipped", {loop, {0.1, -0.8, -1.0}, {}, {0.0, 1.0, -0.2}, 0.0, pos}},
        {"cgal-man alternating, clipped", {man, front, {}, {0.0, 0.0, -1.0}, 0.0, ab, 24, 0.55}},
        {"cgal-man positive, side view", {man, {1.0, -0.2, 0.1}, {}, {-1.0, 0.1, 0.0}, -0.05, pos, 24, 0.6}},
        {"cgal-man parity", {man, {0.3, 0.4, -1.0}, {}, {}, 0.0, par, 24, 0.6}},
        {"spot alternating, clipped", {spot, front, {}, {0.3, 0.0, -1.0}, 0.0, ab}},
        {"spot camera inside, positive", {spot, {}, glm::dvec3(0.0, 0.1, 0.05), {}, 0.0, pos}},
    };
}

} // namespace

Q_DECLARE_METATYPE(MeshCase)
Q_DECLARE_METATYPE(trimlab::render::FragmentMethodKind)

class TestMethodsOnMeshes : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void agreesWithReference_data();
    void agreesWithReference();

private:
    struct Prepared {
        LoadedScene loaded;
        std::unique_ptr<ReferenceRenderer> reference;
        std::map<std::string, ReferenceResult> results; // per case
    };
    Prepared& prepare(const std::string& source);

    std::unique_ptr<OffscreenGlContext> m_context;
    std::unique_ptr<TrimRenderer> m_renderer;
    std::map<std::string, Prepared> m_scenes;
    std::string m_uploaded;
};

void TestMethodsOnMeshes::initTestCase()
{
    TRIMLAB_INIT_GL_CONTEXT(m_context);
    m_renderer = std::make_unique<TrimRenderer>(m_context->context());
}

void TestMethodsOnMeshes::agreesWithReference_data()
{
    QTest::addColumn<MeshCase>("meshCase");
    QTest::addColumn<FragmentMethodKind>("method");
    for (const auto& [name, meshCase] : meshCases())
        for (const MethodInfo& info : fragmentMethods())
            QTest::newRow(qPrintable(QString("%1: %2").arg(QString::fromLatin1(info.id.data()), name)))
                << meshCase << info.kind;
}

TestMethodsOnMeshes::Prepared& TestMethodsOnMeshes::prepare(const std::string& source)
{
    auto it = m_scenes.find(source);
    if (it == m_scenes.end()) {
        Prepared prepared{loadScene(source), nullptr, {}};
        prepared.reference = std::make_unique<ReferenceRenderer>(prepared.loaded.scene);
        it = m_scenes.emplace(source, std::move(prepared)).first;
    }
    if (m_uploaded != source) {
        m_renderer->setScene(it->second.loaded.scene);
        m_uploaded = source;
    }
    return it->second;
}

void TestMethodsOnMeshes::agreesWithReference()
{
    QFETCH(MeshCase, meshCase);
    QFETCH(FragmentMethodKind, method);
    if (!meshCase.source.starts_with("demo:") && !std::filesystem::exists(meshCase.source))
        QSKIP(qPrintable(QString::fromStdString("shared data missing: " + meshCase.source)));
    Prepared& prepared = prepare(meshCase.source);
    QVERIFY2(prepared.loaded.trimmable(), prepared.loaded.trimUnavailableReason().c_str());

    const Bounds bounds = prepared.loaded.scene.worldBounds();
    test::MethodCase testCase{
        QTest::currentDataTag(), cameraFor(meshCase, bounds), settingsFor(meshCase, bounds), {}, kWidth, kHeight};
    testCase.parameters.k = meshCase.k;
    const std::string tag = QTest::currentDataTag();
    const std::string key = tag.substr(tag.find(": ") + 2); // the case, shared by all methods
    auto result = prepared.results.find(key);
    if (result == prepared.results.end())
        result = prepared.results
                     .emplace(key, prepared.reference->render(testCase.camera, kWidth, kHeight, testCase.settings))
                     .first;
    QString summary;
    const auto failure =
        test::checkMethodAgainstReference(*m_renderer, method, testCase, *prepared.reference, result->second, &summary);
    qInfo("%s", qPrintable(summary));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
}

QTEST_MAIN(TestMethodsOnMeshes)
#include "tst_methods_on_meshes.moc"
