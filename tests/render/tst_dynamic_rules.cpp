// The dynamic rules on the GPU (thesis Algorithms 8.11–8.13, render/dynamic_trim_renderer)
// against the exact CPU reference (core/trim/dynamic_reference_renderer): a sphere whose
// north cap is pushed down through its south side in a first set of deformations, then a
// side cap pushed through the opposite side in a second set. Every method that can hold
// reference and current fragments together, every dynamic rule, one and two sets, with
// and without a clip plane: >= 99.9 % of compared pixels agree.
#include "gl_test_context.h"
#include "method_check.h"

#include "render/dynamic_trim_renderer.h"
#include "core/scene/shape_generators.h"
#include "core/trim/dynamic_chain.h"
#include "core/trim/dynamic_reference_renderer.h"

#include <glm/geometric.hpp>

#include <QtTest>

#include <map>
#include <set>

using namespace trimlab;
using namespace trimlab::render;

namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;

// Moves the cap of the unit sphere around `axis` (points with axis·p > start) by
// `displacement`, with a smooth falloff so the surface stays a closed immersion.
std::vector<glm::vec3> pushCap(std::vector<glm::vec3> positions, const glm::dvec3& axis, double start,
                               const glm::dvec3& displacement)
{
    for (glm::vec3& p : positions) {
        const double along = glm::dot(glm::dvec3(p), axis);
        if (along <= start)
            continue;
        const double t = std::min(1.0, (along - start) / (1.0 - start));
        const double falloff = t * t * (3.0 - 2.0 * t);
        p = glm::vec3(glm::dvec3(p) + displacement * falloff);
    }
    return positions;
}

// Set 1 pushes the north cap down through the south side: a finger whose part below the
// sphere has w = −1. Set 2 extrudes a bump from the sphere's lower side into that part
// (thesis Fig. 8.7 in 3D: the extension enters a negative region).
std::vector<glm::vec3> firstSet(const std::vector<glm::vec3>& base)
{
    return pushCap(base, {0.0, 1.0, 0.0}, 0.55, {0.0, -2.3, 0.0});
}
std::vector<glm::vec3> secondSet(const std::vector<glm::vec3>& first)
{
    return pushCap(first, glm::normalize(glm::dvec3(0.6, -0.8, 0.0)), 0.8, {-0.75, -0.45, 0.0});
}

struct ChainCase {
    int sets = 1;
    DynamicRule rule = DynamicRule::Confluent;
    bool clipped = false;
};

DynamicChain makeChain(const TriangleMesh& sphere, const ChainCase& c)
{
    const std::vector<glm::vec3> base = sphere.positions;
    const std::vector<glm::vec3> first = firstSet(base);
    std::vector<std::vector<glm::vec3>> frames{base, first};
    std::vector<DynamicRule> rules{c.sets == 1 ? c.rule : DynamicRule::Confluent};
    if (c.sets == 2) {
        frames.push_back(secondSet(first));
        rules.push_back(c.rule);
    }
    return makeDynamicChain(sphere.triangles, frames, rules, StaticRule::AlternatingBorder);
}

Camera chainCamera()
{
    Bounds bounds;
    bounds.extend(glm::dvec3(-1.0, -1.4, -1.0));
    bounds.extend(glm::dvec3(1.0, 1.0, 1.0));
    return withDepthRange(fitCamera(bounds, double(kWidth) / kHeight, {-0.2, 0.35, -1.0}), bounds);
}

TrimSettings chainSettings(const ChainCase& c)
{
    TrimSettings settings;
    if (c.clipped)
        settings.clip = ClipPlane{true, glm::normalize(glm::dvec3(0.2, 0.1, -1.0)), 0.05};
    return settings;
}

QString caseName(const ChainCase& c)
{
    return QStringLiteral("%1 set%2 %3%4")
        .arg(c.sets)
        .arg(c.sets == 1 ? "" : "s")
        .arg(QString::fromLatin1(dynamicRuleName(c.rule).data()))
        .arg(c.clipped ? " clipped" : "");
}

} // namespace

Q_DECLARE_METATYPE(ChainCase)
Q_DECLARE_METATYPE(trimlab::render::FragmentMethodKind)

class TestDynamicRulesGpu : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void agreesWithReference_data();
    void agreesWithReference();
    void dynamicDiffersFromStaticWhereTheSweptRegionIsKept();
    void peelingMethodsRefuseWithAReason();
    void characterizationIsCachedWhileTheViewStays();
    void appendedLevelsCarryTheCharacterization();
    void overflowIsForgottenWhereThePixelEmpties();
    void shownVertexColorsReplaceThePalette();

private:
    const ReferenceResult& referenceFor(const ChainCase& c);

    std::unique_ptr<OffscreenGlContext> m_context;
    std::unique_ptr<TrimRenderer> m_renderer;
    std::unique_ptr<DynamicTrimRenderer> m_dynamic;
    TriangleMesh m_sphere;
    std::map<QString, ReferenceResult> m_references;
};

void TestDynamicRulesGpu::initTestCase()
{
    TRIMLAB_INIT_GL_CONTEXT(m_context);
    m_renderer = std::make_unique<TrimRenderer>(m_context->context());
    m_dynamic = std::make_unique<DynamicTrimRenderer>(*m_renderer);
    m_sphere = makeIcosphere({0.0, 0.0, 0.0}, 1.0, 4);
}

void TestDynamicRulesGpu::agreesWithReference_data()
{
    QTest::addColumn<ChainCase>("chainCase");
    QTest::addColumn<FragmentMethodKind>("method");
    std::vector<ChainCase> cases;
    for (DynamicRule rule : {DynamicRule::Confluent, DynamicRule::ConstructiveAdditive,
                             DynamicRule::ConstructiveSubtractive, DynamicRule::ConstructiveIntersection})
        for (int sets : {1, 2})
            // After a second intersection almost nothing is left: a vacuous image.
            if (sets == 1 || rule != DynamicRule::ConstructiveIntersection)
                cases.push_back({sets, rule, false});
    cases.push_back({2, DynamicRule::Confluent, true});
    cases.push_back({1, DynamicRule::ConstructiveAdditive, true});
    for (const ChainCase& c : cases)
        for (const MethodInfo& info : fragmentMethods())
            if (info.dynamicRules)
                QTest::newRow(qPrintable(QString("%1: %2").arg(QString::fromLatin1(info.id.data()), caseName(c))))
                    << c << info.kind;
}

const ReferenceResult& TestDynamicRulesGpu::referenceFor(const ChainCase& c)
{
    const QString key = caseName(c);
    auto found = m_references.find(key);
    if (found == m_references.end())
        found = m_references
                    .emplace(key, DynamicReferenceRenderer(makeChain(m_sphere, c))
                                      .render(chainCamera(), kWidth, kHeight, chainSettings(c)))
                    .first;
    return found->second;
}

void TestDynamicRulesGpu::agreesWithReference()
{
    QFETCH(ChainCase, chainCase);
    QFETCH(FragmentMethodKind, method);
    test::MethodCase testCase{caseName(chainCase), chainCamera(), chainSettings(chainCase), {}, kWidth, kHeight};
    testCase.parameters.k = 32; // deep enough for every pixel of the two-set chain
    m_renderer->setMethod(method);
    m_renderer->setParameters(testCase.parameters);
    m_dynamic->setChain(makeChain(m_sphere, chainCase));
    m_dynamic->render(testCase.camera, testCase.settings, kWidth, kHeight);
    QString summary;
    const auto failure = test::checkFrameAgainstReference(*m_renderer, testCase, referenceFor(chainCase), {}, &summary);
    if (failure)
        QFAIL(qPrintable(*failure));
    qInfo("%s", qPrintable(summary));
}

void TestDynamicRulesGpu::dynamicDiffersFromStaticWhereTheSweptRegionIsKept()
{
    // The bump of the second set enters the finger's part below the sphere (w = −1), where
    // the current index becomes 0: the static rule cuts it away, the confluent rule keeps
    // the swept volume interior. The images must differ, and only where the bump is (the
    // pixels showing triangles the second set moved, under either rule).
    const ChainCase c{2, DynamicRule::Confluent, true};
    const DynamicChain chain = makeChain(m_sphere, c);
    const ReferenceResult dynamic = referenceFor(c);
    Scene current;
    current.objects.push_back(
        {"current", {chain.levels.back().frame.scene.objects[0].mesh.positions, m_sphere.triangles}, glm::dmat4(1.0)});
    const ReferenceResult staticResult =
        ReferenceRenderer(current).render(chainCamera(), kWidth, kHeight, chainSettings(c));
    const auto& movedTriangles = chain.levels.back().frame.meshTriangle[kDynamicObjectCurrentOnly];
    const std::set<std::uint32_t> moved(movedTriangles.begin(), movedTriangles.end());
    int differing = 0;
    int differingOutsideFinger = 0;
    for (std::size_t i = 0; i < dynamic.trim.pixels.size(); ++i) {
        const TrimPixel& d = dynamic.trim.pixels[i];
        const TrimPixel& s = staticResult.trim.pixels[i];
        const int dMesh =
            d.covered()
                ? int(chain.levels.back().frame.meshTriangle[std::size_t(d.objectId)][std::size_t(d.primitiveId)])
                : -1;
        if (dMesh == s.primitiveId)
            continue;
        ++differing;
        const bool finger = (dMesh >= 0 && moved.count(std::uint32_t(dMesh))) ||
                            (s.covered() && moved.count(std::uint32_t(s.primitiveId)));
        differingOutsideFinger += finger ? 0 : 1;
    }
    QVERIFY2(differing > 50, qPrintable(QString("only %1 pixels differ").arg(differing)));
    QCOMPARE(differingOutsideFinger, 0);
}

void TestDynamicRulesGpu::peelingMethodsRefuseWithAReason()
{
    m_renderer->setMethod(FragmentMethodKind::PeelingF2B);
    m_dynamic->setChain(makeChain(m_sphere, {}));
    try {
        m_dynamic->render(chainCamera(), TrimSettings{}, kWidth, kHeight);
        QFAIL("F2B peeling ran the dynamic rules");
    } catch (const std::invalid_argument& error) {
        QVERIFY(QString::fromUtf8(error.what()).contains("Pick a buffer method"));
    }
}

void TestDynamicRulesGpu::characterizationIsCachedWhileTheViewStays()
{
    m_renderer->setMethod(FragmentMethodKind::ABufferLinkedList);
    const ChainCase c{2, DynamicRule::Confluent, false};
    const DynamicChain chain = makeChain(m_sphere, c);
    m_dynamic->setChain(chain);
    m_dynamic->render(chainCamera(), TrimSettings{}, kWidth, kHeight);
    QCOMPARE(m_dynamic->lastStats().characterizedLevels, 1);
    const TrimImage first = m_renderer->readTrimImage();
    m_dynamic->setShownLevel(chain.levels.back());
    m_dynamic->render(chainCamera(), TrimSettings{}, kWidth, kHeight);
    QCOMPARE(m_dynamic->lastStats().characterizedLevels, 0);
    const TrimImage second = m_renderer->readTrimImage();
    for (std::size_t i = 0; i < first.pixels.size(); ++i)
        QCOMPARE(second.pixels[i].primitiveId, first.pixels[i].primitiveId);
    Camera moved = chainCamera();
    moved.eye.x += 0.1;
    m_dynamic->render(moved, TrimSettings{}, kWidth, kHeight);
    QCOMPARE(m_dynamic->lastStats().characterizedLevels, 1);
}

void TestDynamicRulesGpu::appendedLevelsCarryTheCharacterization()
{
    // A history played forward one frame at a time (an animation against its previous
    // pose): appending each frame characterizes one level per render, and every frame's
    // image equals the one of the whole chain set at once, which agrees with the exact
    // reference. The frames: the two sets' deformations, each split in two steps.
    m_renderer->setMethod(FragmentMethodKind::ABufferLinkedList);
    m_renderer->setParameters(MethodParameters{});
    const std::vector<glm::vec3> base = m_sphere.positions;
    const std::vector<glm::vec3> half = pushCap(base, {0.0, 1.0, 0.0}, 0.55, {0.0, -1.15, 0.0});
    const std::vector<glm::vec3> first = firstSet(base);
    const std::vector<glm::vec3> second = secondSet(first);
    const std::vector<std::vector<glm::vec3>> frames{base, half, first, second};
    const Camera camera = chainCamera();
    for (std::size_t shown = 1; shown < frames.size(); ++shown) {
        const std::vector<std::vector<glm::vec3>> prefix(frames.begin(), frames.begin() + std::ptrdiff_t(shown) + 1);
        const DynamicChain whole =
            makeDynamicChain(m_sphere.triangles, prefix, std::vector<DynamicRule>(shown, DynamicRule::Confluent),
                             StaticRule::AlternatingBorder);
        if (shown == 1) {
            m_dynamic->setChain(whole);
        } else {
            m_dynamic->appendLevel(whole.levels.back());
        }
        QCOMPARE(m_dynamic->levelCount(), int(shown));
        m_dynamic->render(camera, TrimSettings{}, kWidth, kHeight);
        QCOMPARE(m_dynamic->lastStats().characterizedLevels, shown == 1 ? 0 : 1);
        const TrimImage appended = m_renderer->readTrimImage();

        test::MethodCase testCase{QStringLiteral("frame %1").arg(shown), camera, TrimSettings{}, {}, kWidth, kHeight};
        const ReferenceResult reference =
            DynamicReferenceRenderer(whole).render(camera, kWidth, kHeight, TrimSettings{});
        QString summary;
        if (const auto failure = test::checkFrameAgainstReference(*m_renderer, testCase, reference, {}, &summary))
            QFAIL(qPrintable(*failure));
        qInfo("appended, frame %d: %s", int(shown), qPrintable(summary));

        DynamicTrimRenderer fresh(*m_renderer);
        fresh.setChain(whole);
        fresh.render(camera, TrimSettings{}, kWidth, kHeight);
        QCOMPARE(fresh.lastStats().characterizedLevels, int(shown) - 1);
        const TrimImage wholeImage = m_renderer->readTrimImage();
        int differing = 0;
        for (std::size_t i = 0; i < appended.pixels.size(); ++i)
            differing += appended.pixels[i].objectId != wholeImage.pixels[i].objectId ||
                                 appended.pixels[i].primitiveId != wholeImage.pixels[i].primitiveId
                             ? 1
                             : 0;
        QCOMPARE(differing, 0);
    }
    // The whole chain, characterized by the fresh renderers above, left this one's cache
    // alone: one more frame of the same view characterizes nothing.
    m_dynamic->render(camera, TrimSettings{}, kWidth, kHeight);
    QCOMPARE(m_dynamic->lastStats().characterizedLevels, 0);
}

// A pixel whose fragments overflowed a small k-buffer in one frame cannot know its
// classification in the next (its reference is uncertain there), but once the surface
// has left the pixel the ray crosses no reference surface, and the one interval it has,
// behind every surface, is outside under every rule: the pixel is background again, as
// the exact reference says, instead of staying unresolved (magenta) for the rest of the
// history. The frames: the sphere, the north cap pushed through the south side (deep
// pixels), then the whole mesh moved out of the view twice.
void TestDynamicRulesGpu::overflowIsForgottenWhereThePixelEmpties()
{
    m_renderer->setMethod(FragmentMethodKind::KPlusArray);
    MethodParameters parameters;
    parameters.k = 3;
    m_renderer->setParameters(parameters);
    const std::vector<glm::vec3> base = m_sphere.positions;
    const std::vector<glm::vec3> first = firstSet(base);
    std::vector<glm::vec3> away = first;
    for (glm::vec3& p : away)
        p.x += 20.0f;
    std::vector<glm::vec3> further = away;
    for (glm::vec3& p : further)
        p.x += 1.0f;
    const std::vector<std::vector<glm::vec3>> frames{base, first, away, further};
    const Camera camera = chainCamera();
    std::vector<std::uint64_t> unresolved;
    std::vector<std::uint64_t> overflowed;
    for (std::size_t shown = 1; shown < frames.size(); ++shown) {
        const std::vector<std::vector<glm::vec3>> prefix(frames.begin(), frames.begin() + std::ptrdiff_t(shown) + 1);
        const DynamicChain chain =
            makeDynamicChain(m_sphere.triangles, prefix, std::vector<DynamicRule>(shown, DynamicRule::Confluent),
                             StaticRule::AlternatingBorder);
        m_dynamic->setChain(chain);
        m_dynamic->render(camera, TrimSettings{}, kWidth, kHeight);
        unresolved.push_back(m_renderer->lastStats().counts.unresolvedPixels);
        overflowed.push_back(m_renderer->lastStats().counts.overflowPixels);
    }
    qInfo("overflowed pixels per frame: %llu, %llu, %llu; unresolved: %llu, %llu, %llu",
          static_cast<unsigned long long>(overflowed[0]), static_cast<unsigned long long>(overflowed[1]),
          static_cast<unsigned long long>(overflowed[2]), static_cast<unsigned long long>(unresolved[0]),
          static_cast<unsigned long long>(unresolved[1]), static_cast<unsigned long long>(unresolved[2]));
    QVERIFY(overflowed[0] > 0); // k = 3 is too shallow for the pushed cap: the case arises
    QVERIFY(unresolved[1] > 0); // moved away from overflowed pixels: honestly uncertain
    QCOMPARE(unresolved[2], std::uint64_t(0));
    const TrimImage image = m_renderer->readTrimImage();
    for (const TrimPixel& pixel : image.pixels)
        QVERIFY(!pixel.covered() && !pixel.unresolved);
}

void TestDynamicRulesGpu::shownVertexColorsReplaceThePalette()
{
    // The brush's hover tint under the dynamic rules: per mesh vertex colors reach every
    // frame-class object of the shown level, and survive replacing the shown level.
    m_renderer->setMethod(FragmentMethodKind::ABufferLinkedList);
    const DynamicChain chain = makeChain(m_sphere, {});
    m_dynamic->setChain(chain);
    const std::vector<std::uint32_t> green(m_sphere.positions.size(), 0xFF00FF00u);
    m_dynamic->setShownVertexColors(green);
    m_dynamic->setShownLevel(chain.levels.back());
    m_dynamic->render(chainCamera(), TrimSettings{}, kWidth, kHeight);
    const QImage image = m_renderer->readColor();
    const TrimImage ids = m_renderer->readTrimImage();
    int covered = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            if (ids.at(x, y).covered()) {
                ++covered;
                const QRgb c = image.pixel(x, y);
                QVERIFY2(qGreen(c) > qRed(c) && qGreen(c) > qBlue(c), qPrintable(QString("pixel %1,%2").arg(x).arg(y)));
            }
    QVERIFY(covered > 1000);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, m_dynamic->setShownVertexColors({1u, 2u}));
    m_dynamic->setShownVertexColors({});
}

QTEST_MAIN(TestDynamicRulesGpu)
#include "tst_dynamic_rules.moc"
