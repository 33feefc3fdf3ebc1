// Interior inspection on the GPU against the exact CPU reference (tests/support/
// method_check.h, >= 99.9 % of compared pixels): multi-plane clipping (a box) and capping
// with every method, n-ary CSG (union, intersection, difference, a 3-operand tree) of
// self-crossing demo surfaces and of a real mesh placed twice with its own transforms,
// with capping and collision highlighting, on every buffer method, the walls a difference
// carved in their own color; and the clear refusal of the methods that cannot carry the
// per-object walk.
#include "gl_test_context.h"
#include "method_check.h"
#include "reference_scene_cache.h"
#include "test_paths.h"

#include "core/catalog/demo_scenes.h"
#include "core/catalog/scene_source.h"
#include "core/scene/shape_generators.h"
#include "core/trim/reference_renderer.h"
#include "core/trim/trim_shading.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <QColor>
#include <QtTest>

using namespace trimlab;
using namespace trimlab::render;

namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;

CsgExpression expression(const char* text)
{
    std::string error;
    const std::optional<CsgExpression> e = parseCsgExpression(text, &error);
    if (!e)
        qFatal("bad expression %s: %s", text, error.c_str());
    return *e;
}

// The spot mesh twice: object 0 as loaded, object 1 turned by 70 degrees about y,
// scaled by 0.8 and shifted, so that the two overlap in their bodies.
Scene twoSpots()
{
    const Scene spot = loadScene(test::sharedDataPath("static/odedstein-spot_low_resolution.obj.gz").string()).scene;
    Scene scene;
    scene.objects.push_back({"spot", spot.objects[0].mesh, glm::dmat4(1.0)});
    glm::dmat4 model = glm::translate(glm::dmat4(1.0), glm::dvec3(0.25, 0.1, 0.15));
    model = glm::rotate(model, glm::radians(70.0), glm::dvec3(0.0, 1.0, 0.0));
    model = glm::scale(model, glm::dvec3(0.8));
    scene.objects.push_back({"spot turned", spot.objects[0].mesh, model});
    return scene;
}

Scene sceneNamed(const std::string& name)
{
    if (name == "two-spots")
        return twoSpots();
    return *makeDemoScene(name);
}

// The settings of one case, on `bounds` (planes through the scene's centre).
TrimSettings caseSettings(const QString& which, const Bounds& bounds)
{
    TrimSettings s;
    const glm::dvec3 c = bounds.center();
    const double r = bounds.radius();
    const ClipPlane tilted{true, glm::normalize(glm::dvec3(0.3, -0.2, -1.0)), 0.0};
    auto through = [&](ClipPlane p, double shift) {
        p.offset = -glm::dot(p.normal, c) + shift * r;
        return p;
    };
    const ClipSet box =
        ClipSet::box(c - glm::dvec3(0.45 * r, 0.5 * r, 0.6 * r), c + glm::dvec3(0.35 * r, 0.4 * r, 0.1 * r));
    if (which == "box") {
        s.setClipSet(box);
    } else if (which == "box capped") {
        s.setClipSet(box);
        s.cap.enabled = true;
    } else if (which == "plane capped") {
        s.clip = through(tilted, 0.05);
        s.cap.enabled = true;
    } else if (which == "union capped") {
        s.csg.expression = expression("0 | 1");
        s.clip = through(tilted, 0.0);
        s.cap.enabled = true;
    } else if (which == "intersection") {
        s.csg.expression = expression("0 & 1");
        s.rule = StaticRule::PositiveIndex;
    } else if (which == "difference capped") {
        s.csg.expression = expression("0 - 1");
        s.clip = through(tilted, -0.1);
        s.cap.enabled = true;
    } else if (which == "tree box capped") {
        s.csg.expression = expression("(0 | 2) - 1");
        s.setClipSet(box);
        s.cap.enabled = true;
        s.highlight.collisions = true;
    } else if (which == "tree per-object rules") {
        s.csg.expression = expression("0 & 1 | 2");
        s.csg.objectRules[0] = StaticRule::Parity;
        s.csg.objectRules[2] = StaticRule::PositiveIndex;
        s.clip = through(tilted, 0.1);
    } else if (which == "collisions") {
        s.rule = StaticRule::Parity;
        s.clip = through(tilted, 0.0);
        s.highlight.collisions = true;
    }
    return s;
}

} // namespace

Q_DECLARE_METATYPE(trimlab::render::FragmentMethodKind)

class TestInspectMethods : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void agreesWithReference_data();
    void agreesWithReference();
    void peelingMethodsRefuseThePerObjectWalk();
    void badExpressionsAreRefused();
    void framesCountCapsAndCollisions();
    void carvedWallsHaveTheirColor();

private:
    test::ReferenceSceneCache::Entry& prepare(const std::string& name) { return m_scenes.prepare(*m_renderer, name); }

    std::unique_ptr<OffscreenGlContext> m_context;
    std::unique_ptr<TrimRenderer> m_renderer;
    test::ReferenceSceneCache m_scenes{sceneNamed};
};

void TestInspectMethods::initTestCase()
{
    TRIMLAB_INIT_GL_CONTEXT(m_context);
    m_renderer = std::make_unique<TrimRenderer>(m_context->context());
}

void TestInspectMethods::agreesWithReference_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<QString>("settings");
    QTest::addColumn<FragmentMethodKind>("method");
    struct Case {
        const char* scene;
        const char* settings;
        bool perObject; // needs a buffer method
    };
    const Case cases[] = {
        {"pushed-sphere", "box", false},          {"pushed-sphere", "box capped", false},
        {"crossing-loop", "plane capped", false}, {"csg-trio", "union capped", true},
        {"csg-trio", "intersection", true},       {"csg-trio", "difference capped", true},
        {"csg-trio", "tree box capped", true},    {"csg-trio", "tree per-object rules", true},
        {"csg-trio", "collisions", true},         {"two-spots", "difference capped", true},
        {"two-spots", "intersection", true},
    };
    for (const Case& c : cases)
        for (const MethodInfo& info : fragmentMethods())
            if (info.inspection || !c.perObject)
                QTest::newRow(
                    qPrintable(QString("%1 %2 %3").arg(QString::fromLatin1(info.id.data()), c.scene, c.settings)))
                    << QString(c.scene) << QString(c.settings) << info.kind;
}

void TestInspectMethods::agreesWithReference()
{
    QFETCH(QString, scene);
    QFETCH(QString, settings);
    QFETCH(FragmentMethodKind, method);
    test::ReferenceSceneCache::Entry& prepared = prepare(scene.toStdString());
    const Bounds bounds = prepared.scene.worldBounds();
    Camera camera = fitCamera(bounds, double(kWidth) / kHeight);
    if (settings == "intersection") { // the common part is small: move closer to it
        camera.eye = camera.target + 0.6 * (camera.eye - camera.target);
        camera = withDepthRange(camera, bounds);
    }
    test::MethodCase testCase{QTest::currentDataTag(), camera, {}, {}, kWidth, kHeight};
    testCase.settings = caseSettings(settings, bounds);
    testCase.parameters.k = 32; // the nested sheets of csg-trio exceed 16 in places
    const ReferenceResult& reference = m_scenes.referenceResult(scene.toStdString(), settings.toStdString(),
                                                                testCase.camera, kWidth, kHeight, testCase.settings);
    QString summary;
    const auto failure =
        test::checkMethodAgainstReference(*m_renderer, method, testCase, prepared.reference, reference, &summary);
    qInfo("%s; %llu caps, %llu collisions", qPrintable(summary),
          static_cast<unsigned long long>(m_renderer->lastStats().counts.capPixels),
          static_cast<unsigned long long>(m_renderer->lastStats().counts.collisionPixels));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
}

void TestInspectMethods::peelingMethodsRefuseThePerObjectWalk()
{
    const Camera camera = fitCamera(prepare("csg-trio").scene.worldBounds(), double(kWidth) / kHeight);
    TrimSettings settings;
    settings.csg.expression = expression("0 | 1");
    for (FragmentMethodKind kind :
         {FragmentMethodKind::PeelingF2B, FragmentMethodKind::PeelingDual, FragmentMethodKind::TwoPass}) {
        m_renderer->setMethod(kind);
        const std::string name(methodInfo(kind).displayName);
        try {
            m_renderer->render(camera, settings, kWidth, kHeight);
            QFAIL(qPrintable(QString::fromStdString(name) + " rendered CSG instead of refusing it"));
        } catch (const std::invalid_argument& e) {
            const std::string message = e.what();
            QVERIFY2(message.find(name) != std::string::npos && message.find("CSG") != std::string::npos &&
                         message.find("buffer method") != std::string::npos,
                     e.what());
        }
    }
    // The coplanar highlight is refused alike; capping is not.
    m_renderer->setMethod(FragmentMethodKind::PeelingF2B);
    settings = TrimSettings{};
    settings.highlight.coplanar = true;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, m_renderer->render(camera, settings, kWidth, kHeight));
    settings = TrimSettings{};
    settings.clip = ClipPlane{true, {0.0, 0.0, -1.0}, 0.0};
    settings.cap.enabled = true;
    m_renderer->render(camera, settings, kWidth, kHeight);
    QVERIFY(m_renderer->lastStats().counts.capPixels > 0);
}

void TestInspectMethods::badExpressionsAreRefused()
{
    const Scene& oneObject = prepare("pushed-sphere").scene;
    const Camera camera = fitCamera(oneObject.worldBounds(), double(kWidth) / kHeight);
    m_renderer->setMethod(FragmentMethodKind::KPlusArray);
    TrimSettings settings;
    settings.csg.expression = expression("0 - 2");
    try {
        m_renderer->render(camera, settings, kWidth, kHeight);
        QFAIL("an expression naming a missing object rendered");
    } catch (const std::invalid_argument& e) {
        QVERIFY2(std::string(e.what()).find("object 2") != std::string::npos, e.what());
    }
}

void TestInspectMethods::framesCountCapsAndCollisions()
{
    // The frame counters the status bar shows equal the counts of the read-back image.
    const test::ReferenceSceneCache::Entry& prepared = prepare("csg-trio");
    const Bounds bounds = prepared.scene.worldBounds();
    const Camera camera = fitCamera(bounds, double(kWidth) / kHeight);
    const TrimSettings settings = caseSettings("tree box capped", bounds);
    m_renderer->setMethod(FragmentMethodKind::ABufferLinkedList);
    m_renderer->render(camera, settings, kWidth, kHeight);
    const TrimImage image = m_renderer->readTrimImage();
    std::uint64_t caps = 0, collisions = 0;
    for (const TrimPixel& p : image.pixels) {
        caps += p.isCap() ? 1 : 0;
        collisions += p.collision ? 1 : 0;
    }
    QVERIFY(caps > 100);
    QVERIFY(collisions > 20);
    QCOMPARE(m_renderer->lastStats().counts.capPixels, caps);
    QCOMPARE(m_renderer->lastStats().counts.collisionPixels, collisions);
}

// A ball bitten out of the top of a sphere (0 - 1) seen from above: on every method that
// takes CSG, the cavity's floor — the ball's inside — has the carved-wall color of the CPU
// reference (trim_shading.h), not the blue of an inside seen through a cut.
void TestInspectMethods::carvedWallsHaveTheirColor()
{
    Scene scene;
    scene.objects.push_back({"sphere", makeIcosphere(glm::dvec3(0.0), 1.0, 4), glm::dmat4(1.0)});
    scene.objects.push_back({"ball", makeIcosphere({0.0, 0.0, 1.0}, 0.5, 3), glm::dmat4(1.0)});
    Camera camera;
    camera.eye = {0.0, 0.0, 4.0};
    camera = withDepthRange(camera, scene.worldBounds());
    TrimSettings settings;
    settings.rule = StaticRule::Nonzero;
    settings.csg.expression = expression("0 - 1");
    constexpr int kSide = 61;
    const ReferenceResult reference = ReferenceRenderer(scene).render(camera, kSide, kSide, settings, 1);
    const std::uint8_t* expected = reference.color.at(kSide / 2, kSide / 2);
    QCOMPARE(reference.trim.at(kSide / 2, kSide / 2).objectId, 1);
    QVERIFY(std::abs(int(expected[0]) - int(std::lround(255 * kCarvedWallColor[0]))) <= 2);
    m_renderer->setScene(scene);
    for (const MethodInfo& info : fragmentMethods()) {
        if (!info.inspection)
            continue;
        m_renderer->setMethod(info.kind);
        m_renderer->render(camera, settings, kSide, kSide);
        const QColor shown = m_renderer->readColor().pixelColor(kSide / 2, kSide / 2);
        const int channels[3] = {shown.red(), shown.green(), shown.blue()};
        for (int c = 0; c < 3; ++c)
            QVERIFY2(std::abs(channels[c] - int(expected[c])) <= 3,
                     qPrintable(QStringLiteral("%1: %2 instead of %3, %4, %5")
                                    .arg(QString::fromLatin1(info.id.data()), shown.name())
                                    .arg(expected[0])
                                    .arg(expected[1])
                                    .arg(expected[2])));
    }
}

QTEST_MAIN(TestInspectMethods)
#include "tst_inspect_methods.moc"
