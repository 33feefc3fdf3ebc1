// Every multi-fragment method × the thesis's three static rules × two clip planes (and the
// nonzero, negative and threshold rules through one) × three scenes against the CPU reference (issue: multi-fragment backends): a self-crossing surface, coplanar
// duplicated triangles (a doubly covered sphere: depth ties), and 17 nested spheres (34
// layers through the centre, beyond k = 16). Exact methods must agree everywhere;
// bounded ones wherever they report no overflow, and report overflow wherever they are
// wrong. tests/support/method_check.h holds the criteria.
#include "gl_test_context.h"
#include "method_check.h"
#include "reference_scene_cache.h"

#include "core/catalog/demo_scenes.h"
#include "core/scene/shape_generators.h"

#include <glm/geometric.hpp>

#include <utility>
#include <vector>

#include <QtTest>

using namespace trimlab;
using namespace trimlab::render;

namespace {

constexpr int kWidth = 200;
constexpr int kHeight = 150;
constexpr int kNestedSpheres = 17;

Scene doublyCoveredSphere()
{
    const TriangleMesh sphere = makeIcosphere(glm::dvec3(0.0), 1.0, 3);
    Scene scene;
    scene.objects.push_back({"sphere", sphere, glm::dmat4(1.0)});
    scene.objects.push_back({"same sphere", sphere, glm::dmat4(1.0)});
    return scene;
}

Scene nestedSpheres()
{
    TriangleMesh all;
    for (int i = 0; i < kNestedSpheres; ++i)
        appendMesh(all, makeIcosphere(glm::dvec3(0.0), 1.0 - 0.05 * i, 2));
    Scene scene;
    scene.objects.push_back({"nested spheres", all, glm::dmat4(1.0)});
    return scene;
}

// The nested spheres turned inside out: w runs down to -17 towards the centre.
Scene insideOutNestedSpheres()
{
    Scene scene = nestedSpheres();
    for (glm::uvec3& t : scene.objects.front().mesh.triangles)
        std::swap(t.y, t.z);
    return scene;
}

Scene sceneNamed(const std::string& name)
{
    if (name == "doubly-covered")
        return doublyCoveredSphere();
    if (name == "nested-17")
        return nestedSpheres();
    if (name == "inside-out-17")
        return insideOutNestedSpheres();
    return *makeDemoScene(name);
}

ClipPlane clipPlane(int which, const Bounds& bounds)
{
    const glm::dvec3 n = glm::normalize(which == 0 ? glm::dvec3(0.0, 0.0, -1.0) : glm::dvec3(0.5, -0.4, -1.0));
    const double shift = which == 0 ? 0.0 : 0.15 * bounds.radius();
    return ClipPlane{true, n, -glm::dot(n, bounds.center()) + shift};
}

} // namespace

Q_DECLARE_METATYPE(trimlab::render::FragmentMethodKind)
Q_DECLARE_METATYPE(trimlab::StaticRule)

class TestMethodMatrix : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void agreesWithReference_data();
    void agreesWithReference();

private:
    std::unique_ptr<OffscreenGlContext> m_context;
    std::unique_ptr<TrimRenderer> m_renderer;
    test::ReferenceSceneCache m_scenes{sceneNamed};
};

void TestMethodMatrix::initTestCase()
{
    TRIMLAB_INIT_GL_CONTEXT(m_context);
    m_renderer = std::make_unique<TrimRenderer>(m_context->context());
}

void TestMethodMatrix::agreesWithReference_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<StaticRule>("rule");
    QTest::addColumn<int>("plane");
    QTest::addColumn<FragmentMethodKind>("method");
    const auto addRow = [](const char* scene, StaticRule rule, int plane, const MethodInfo& info) {
        QTest::newRow(
            qPrintable(QString("%1 %2 %3 plane %4")
                           .arg(QString::fromLatin1(info.id.data()), scene, QString::fromStdString(ruleName(rule)))
                           .arg(plane)))
            << QString(scene) << rule << plane << info.kind;
    };
    for (const char* scene : {"pushed-sphere", "doubly-covered", "nested-17"})
        for (const MethodInfo& info : fragmentMethods())
            for (StaticRule rule : {StaticRule::Parity, StaticRule::PositiveIndex, StaticRule::AlternatingBorder})
                for (int plane : {0, 1})
                    addRow(scene, rule, plane, info);
    // The rules beyond the thesis's three, through the oblique plane only (it cuts every
    // layer), on the scenes where they keep something: the doubly covered sphere has
    // w = 2, the nested spheres up to 17 (K = 9 lies past the k = 16 of the bounded
    // methods), the inside-out nested spheres down to -17.
    const std::pair<StaticRule, std::vector<const char*>> newer[] = {
        {StaticRule::Nonzero, {"pushed-sphere", "doubly-covered", "nested-17"}},
        {StaticRule::Negative, {"inside-out-17"}},
        {StaticRule::atLeast(2), {"doubly-covered", "nested-17"}},
        {StaticRule::atLeast(9), {"nested-17"}},
        {StaticRule::absAtLeast(2), {"doubly-covered", "inside-out-17"}},
    };
    for (const auto& [rule, scenes] : newer)
        for (const char* scene : scenes)
            for (const MethodInfo& info : fragmentMethods())
                addRow(scene, rule, 1, info);
}

void TestMethodMatrix::agreesWithReference()
{
    QFETCH(QString, scene);
    QFETCH(StaticRule, rule);
    QFETCH(int, plane);
    QFETCH(FragmentMethodKind, method);
    const test::ReferenceSceneCache::Entry& prepared = m_scenes.prepare(*m_renderer, scene.toStdString());
    const Bounds bounds = prepared.scene.worldBounds();
    test::MethodCase testCase{
        QTest::currentDataTag(), fitCamera(bounds, double(kWidth) / kHeight), {}, {}, kWidth, kHeight};
    testCase.settings.rule = rule;
    testCase.settings.clip = clipPlane(plane, bounds);
    const std::string key = std::string(ruleName(rule)) + std::to_string(plane);
    const ReferenceResult& reference =
        m_scenes.referenceResult(scene.toStdString(), key, testCase.camera, kWidth, kHeight, testCase.settings);
    QString summary;
    const auto failure =
        test::checkMethodAgainstReference(*m_renderer, method, testCase, prepared.reference, reference, &summary);
    qInfo("%s", qPrintable(summary));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
}

QTEST_MAIN(TestMethodMatrix)
#include "tst_method_matrix.moc"
