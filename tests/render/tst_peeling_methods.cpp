// The multi-pass methods (F2B and DUAL depth peeling, two-pass) on scenes whose answers
// follow by hand from their layer structure: how many geometry passes peeling needs (lock
// flags stop a pixel at its trim fragment; DUAL halves a deep walk), that coincident
// fragments are all peeled, that the pass bound flags what it cuts off instead of showing
// it wrong, and that two-pass shows the first layer only and flags the rest.
#include "gl_test_context.h"
#include "render/trim_renderer.h"

#include "core/catalog/demo_scenes.h"
#include "core/scene/shape_generators.h"
#include "core/trim/reference_renderer.h"

#include <QtTest>

#include <algorithm>
#include <functional>

using namespace trimlab;
using namespace trimlab::render;

namespace {

constexpr int kWidth = 128;
constexpr int kHeight = 96;
constexpr std::uint64_t kPixels = std::uint64_t(kWidth) * kHeight;

// Full-screen quads facing the eye at the origin, layer i at view depth 1 + 0.01 i,
// submitted in a shuffled order (slot s holds layer 37 s mod n; 37 is coprime with the
// layer counts used here), so peeling cannot profit from submission order.
int layerAtSlot(int slot, int layers)
{
    return (slot * 37) % layers;
}
double layerDepth(int layer)
{
    return 1.0 + 0.01 * layer;
}

Scene layeredScene(int layers, const std::function<bool(int)>& frontFacing)
{
    TriangleMesh mesh;
    for (int slot = 0; slot < layers; ++slot) {
        const int layer = layerAtSlot(slot, layers);
        const float z = -float(layerDepth(layer));
        const float s = 10.0f * float(layerDepth(layer)); // far beyond the frustum
        const auto base = static_cast<unsigned>(mesh.positions.size());
        mesh.positions.insert(mesh.positions.end(), {{-s, -s, z}, {s, -s, z}, {s, s, z}, {-s, s, z}});
        if (frontFacing(layer)) // counter-clockwise seen from the eye
            mesh.triangles.insert(mesh.triangles.end(), {{base, base + 1, base + 2}, {base, base + 2, base + 3}});
        else
            mesh.triangles.insert(mesh.triangles.end(), {{base, base + 2, base + 1}, {base, base + 3, base + 2}});
    }
    Scene scene;
    scene.objects.push_back({"layers", mesh, glm::dmat4(1.0)});
    return scene;
}

// The 64 layers of tst_kplus_occupancy: 0..7 back-facing, then front-facing at even and
// back-facing at odd indices. Counted from the far side, the index at the eye is
// 8 + 28 - 28 = 8; walking front to back it falls 8, 7, ..., 0 over layers 0..7 and then
// alternates 1, 0, 1, ... Without trimming the walk stops at layer 0; under the positive
// index rule (interior iff w >= 1) its first boundary is layer 7 (1 -> 0), the 8th layer.
constexpr int kShallowLayers = 64;
Scene shallowTrimScene()
{
    return layeredScene(kShallowLayers, [](int layer) { return layer >= 8 && layer % 2 == 0; });
}

// 32 back-facing layers: the index at the eye is 32 and falls by one per layer, so under
// the positive index rule the only boundary is the last layer (1 -> 0).
constexpr int kDeepLayers = 32;
Scene deepTrimScene()
{
    return layeredScene(kDeepLayers, [](int) { return false; });
}

Camera layerCamera()
{
    Camera camera;
    camera.eye = {0.0, 0.0, 0.0};
    camera.target = {0.0, 0.0, -1.0};
    camera.fovyDegrees = 45.0;
    camera.zNear = 0.01;
    camera.zFar = 10.0;
    return camera;
}

// Two objects with the same icosphere: every fragment has a twin at exactly its depth.
Scene doublyCoveredSphere()
{
    const TriangleMesh sphere = makeIcosphere(glm::dvec3(0.0), 1.0, 3);
    Scene scene;
    scene.objects.push_back({"sphere", sphere, glm::dmat4(1.0)});
    scene.objects.push_back({"same sphere", sphere, glm::dmat4(1.0)});
    return scene;
}

// From the sphere's centre every pixel ray leaves through both copies of one triangle and
// nothing else: no silhouette, exactly two fragments per pixel.
Camera insideSphereCamera()
{
    Camera camera;
    camera.eye = {0.0, 0.0, 0.0};
    camera.target = {0.3, -0.2, -1.0};
    camera.fovyDegrees = 60.0;
    camera.zNear = 0.01;
    camera.zFar = 4.0;
    return camera;
}

TrimSettings untrimmed()
{
    TrimSettings settings;
    settings.trimEnabled = false;
    return settings;
}

TrimSettings positiveIndex()
{
    TrimSettings settings;
    settings.rule = StaticRule::PositiveIndex;
    return settings;
}

// Pixels that show layer `layer` of an n-layer scene with the given facing.
int pixelsShowingLayer(const TrimImage& trim, int layer, int layers, int facing)
{
    int count = 0;
    for (const TrimPixel& p : trim.pixels)
        count += (p.covered() && layerAtSlot(p.primitiveId / 2, layers) == layer && p.facing == facing) ? 1 : 0;
    return count;
}

int pixelsHolding(const PixelOccupancy& occupancy, std::uint32_t held)
{
    return int(std::count(occupancy.held.begin(), occupancy.held.end(), held));
}

} // namespace

Q_DECLARE_METATYPE(trimlab::render::FragmentMethodKind)
Q_DECLARE_METATYPE(glm::dvec3)

class TestPeelingMethods : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void f2bStopsAtTheFirstLayerWithoutTrimming();
    void f2bPeelsUpToTheTrimFragment();
    void dualHalvesTheWalkToADeepTrim();
    void coincidentFragmentsAreAllPeeled_data();
    void coincidentFragmentsAreAllPeeled();
    void passBoundFlagsUnfinishedPixels_data();
    void passBoundFlagsUnfinishedPixels();
    void twoPassDecidesOnlyTheFirstLayer();
    void twoPassOnASelfCrossingSurface_data();
    void twoPassOnASelfCrossingSurface();

private:
    const FrameStats& render(FragmentMethodKind method, const Scene& scene, const Camera& camera,
                             const TrimSettings& settings, int maxPasses = 1024, int width = kWidth,
                             int height = kHeight);

    std::unique_ptr<OffscreenGlContext> m_context;
    std::unique_ptr<TrimRenderer> m_renderer;
    const Scene* m_uploaded = nullptr;
};

void TestPeelingMethods::initTestCase()
{
    TRIMLAB_INIT_GL_CONTEXT(m_context);
    m_renderer = std::make_unique<TrimRenderer>(m_context->context());
}

const FrameStats& TestPeelingMethods::render(FragmentMethodKind method, const Scene& scene, const Camera& camera,
                                             const TrimSettings& settings, int maxPasses, int width, int height)
{
    if (m_uploaded != &scene) {
        m_renderer->setScene(scene);
        m_uploaded = &scene;
    }
    MethodParameters parameters;
    parameters.maxPeelingPasses = maxPasses;
    m_renderer->setMethod(method);
    m_renderer->setParameters(parameters);
    m_renderer->render(camera, settings, width, height);
    return m_renderer->lastStats();
}

// Without trimming every walk ends at the first fragment: the first geometry pass counts
// and finds the nearest depth, the second peels layer 0 everywhere, every pixel locks and
// the occlusion query ends the frame. 2 passes of the 64 a plain F2B would run.
void TestPeelingMethods::f2bStopsAtTheFirstLayerWithoutTrimming()
{
    static const Scene scene = shallowTrimScene();
    const FrameStats stats = render(FragmentMethodKind::PeelingF2B, scene, layerCamera(), untrimmed());
    const TrimImage trim = m_renderer->readTrimImage();
    const PixelOccupancy occupancy = m_renderer->readOccupancy().value();
    QCOMPARE(stats.methodStats.geometryPasses, 2);
    QCOMPARE(pixelsShowingLayer(trim, 0, kShallowLayers, -1), int(kPixels));
    QCOMPARE(pixelsHolding(occupancy, 1), int(kPixels));
    QCOMPARE(stats.counts.fragmentsInSpan, kShallowLayers * kPixels);
    QCOMPARE(stats.counts.fragmentsStored, kPixels);
    QCOMPARE(stats.counts.fragmentsLost, std::uint64_t(0));
    QCOMPARE(stats.counts.unresolvedPixels, std::uint64_t(0));
}

// Positive index: the trim fragment is layer 7, the 8th of the span, so every pixel peels
// 8 fragments and the frame runs 1 + 8 = 9 geometry passes, not 64.
void TestPeelingMethods::f2bPeelsUpToTheTrimFragment()
{
    static const Scene scene = shallowTrimScene();
    const FrameStats stats = render(FragmentMethodKind::PeelingF2B, scene, layerCamera(), positiveIndex());
    const TrimImage trim = m_renderer->readTrimImage();
    const PixelOccupancy occupancy = m_renderer->readOccupancy().value();
    QCOMPARE(stats.methodStats.geometryPasses, 9);
    QCOMPARE(pixelsShowingLayer(trim, 7, kShallowLayers, -1), int(kPixels));
    QCOMPARE(pixelsHolding(occupancy, 8), int(kPixels));
    QCOMPARE(stats.counts.fragmentsStored, 8 * kPixels);
    QCOMPARE(stats.counts.unresolvedPixels, std::uint64_t(0));
}

// The deep scene's trim is its last layer: F2B peels all 32 layers one per pass (1 + 32
// passes); DUAL peels from both ends, its back walk finds the boundary at once but must
// wait for the walks to meet after 16 pairs (1 + 16 passes). On the shallow scene the
// front walk finds layer 7 in its 8th pass, so DUAL runs F2B's 9 passes (with 16 fragments
// peeled per pixel, 8 from each end).
void TestPeelingMethods::dualHalvesTheWalkToADeepTrim()
{
    static const Scene deep = deepTrimScene();
    const FrameStats f2b = render(FragmentMethodKind::PeelingF2B, deep, layerCamera(), positiveIndex());
    QCOMPARE(f2b.methodStats.geometryPasses, 1 + kDeepLayers);
    QCOMPARE(pixelsShowingLayer(m_renderer->readTrimImage(), kDeepLayers - 1, kDeepLayers, -1), int(kPixels));
    const FrameStats dual = render(FragmentMethodKind::PeelingDual, deep, layerCamera(), positiveIndex());
    QCOMPARE(dual.methodStats.geometryPasses, 1 + kDeepLayers / 2);
    QCOMPARE(pixelsShowingLayer(m_renderer->readTrimImage(), kDeepLayers - 1, kDeepLayers, -1), int(kPixels));
    QCOMPARE(pixelsHolding(m_renderer->readOccupancy().value(), kDeepLayers), int(kPixels));
    QCOMPARE(dual.counts.fragmentsStored, kDeepLayers * kPixels);
    QCOMPARE(dual.counts.unresolvedPixels, std::uint64_t(0));

    static const Scene shallow = shallowTrimScene();
    const FrameStats early = render(FragmentMethodKind::PeelingDual, shallow, layerCamera(), positiveIndex());
    QCOMPARE(early.methodStats.geometryPasses, 9);
    QCOMPARE(pixelsShowingLayer(m_renderer->readTrimImage(), 7, kShallowLayers, -1), int(kPixels));
    QCOMPARE(pixelsHolding(m_renderer->readOccupancy().value(), 16), int(kPixels));
}

void TestPeelingMethods::coincidentFragmentsAreAllPeeled_data()
{
    QTest::addColumn<FragmentMethodKind>("method");
    QTest::addColumn<int>("passes");
    // F2B: the counting pass, then one twin per pass. DUAL: both twins in one pass.
    QTest::newRow("F2B") << FragmentMethodKind::PeelingF2B << 3;
    QTest::newRow("DUAL") << FragmentMethodKind::PeelingDual << 2;
}

// Inside the doubly covered sphere the index at the eye is 2; both twins are back-facing,
// so under the positive index rule the walk goes 2 -> 1 -> 0 and its boundary is the
// second twin: every fragment of the span is peeled. A peeling that dropped fragments at
// the depth of the last layer (classic F2B) would peel one per pixel and show none. The
// reference walks ties by object id, so the shown twin is object 1's.
void TestPeelingMethods::coincidentFragmentsAreAllPeeled()
{
    QFETCH(FragmentMethodKind, method);
    QFETCH(int, passes);
    static const Scene scene = doublyCoveredSphere();
    const Camera camera = insideSphereCamera();
    const ReferenceRenderer reference(scene);
    std::uint64_t referenceHits = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const PixelTrace trace = reference.tracePixel(camera, kWidth, kHeight, x, y, positiveIndex());
            referenceHits += trace.walk.walkEnd - trace.walk.walkBegin;
        }
    QCOMPARE(referenceHits, 2 * kPixels);

    const FrameStats stats = render(method, scene, camera, positiveIndex());
    QCOMPARE(stats.counts.fragmentsInSpan, referenceHits);
    QCOMPARE(stats.counts.fragmentsStored, referenceHits);
    QCOMPARE(pixelsHolding(m_renderer->readOccupancy().value(), 2), int(kPixels));
    int shownAsReference = 0;
    for (const TrimPixel& p : m_renderer->readTrimImage().pixels)
        shownAsReference += (p.covered() && p.objectId == 1 && p.facing == -1 && p.windingAtStart == 2) ? 1 : 0;
    QCOMPARE(shownAsReference, int(kPixels));
    QCOMPARE(stats.methodStats.geometryPasses, passes);
}

void TestPeelingMethods::passBoundFlagsUnfinishedPixels_data()
{
    QTest::addColumn<FragmentMethodKind>("method");
    QTest::addColumn<int>("peeledInTwoPasses");
    QTest::newRow("F2B") << FragmentMethodKind::PeelingF2B << 1;
    QTest::newRow("DUAL") << FragmentMethodKind::PeelingDual << 2;
}

// The shallow scene needs 9 passes (positive index). Bounded to 2, each pixel has peeled
// one fragment (DUAL: one from each end) and is still peeling: all are flagged
// unresolved, painted magenta, and their unpeeled fragments counted lost. Bounded to 8,
// still all unresolved; to 9, none.
void TestPeelingMethods::passBoundFlagsUnfinishedPixels()
{
    QFETCH(FragmentMethodKind, method);
    QFETCH(int, peeledInTwoPasses);
    static const Scene scene = shallowTrimScene();
    const FrameStats stats = render(method, scene, layerCamera(), positiveIndex(), 2);
    QCOMPARE(stats.methodStats.geometryPasses, 2);
    int flagged = 0;
    for (const TrimPixel& p : m_renderer->readTrimImage().pixels)
        flagged += (p.unresolved && p.overflowed && !p.covered() && p.windingAtStart == 8) ? 1 : 0;
    QCOMPARE(flagged, int(kPixels));
    QCOMPARE(stats.counts.unresolvedPixels, kPixels);
    QCOMPARE(stats.counts.overflowPixels, kPixels);
    QCOMPARE(stats.counts.fragmentsLost, (kShallowLayers - peeledInTwoPasses) * kPixels);
    QCOMPARE(m_renderer->readColor().pixelColor(kWidth / 2, kHeight / 2), QColor(255, 0, 255));

    QCOMPARE(render(method, scene, layerCamera(), positiveIndex(), 8).counts.unresolvedPixels, kPixels);
    const FrameStats enough = render(method, scene, layerCamera(), positiveIndex(), 9);
    QCOMPARE(enough.counts.unresolvedPixels, std::uint64_t(0));
    QCOMPARE(enough.counts.fragmentsLost, std::uint64_t(0));
    QCOMPARE(pixelsShowingLayer(m_renderer->readTrimImage(), 7, kShallowLayers, -1), int(kPixels));
}

// On the shallow scene the first layer decides without trimming (layer 0 everywhere) and
// never under the positive index rule (the trim is layer 7): then every pixel is
// unresolved, with the 63 fragments behind the first counted lost.
void TestPeelingMethods::twoPassDecidesOnlyTheFirstLayer()
{
    QVERIFY(methodInfo(FragmentMethodKind::TwoPass).bounded);
    static const Scene scene = shallowTrimScene();
    const FrameStats plain = render(FragmentMethodKind::TwoPass, scene, layerCamera(), untrimmed());
    QCOMPARE(plain.methodStats.geometryPasses, 2);
    QCOMPARE(pixelsShowingLayer(m_renderer->readTrimImage(), 0, kShallowLayers, -1), int(kPixels));
    QCOMPARE(plain.counts.unresolvedPixels, std::uint64_t(0));
    QCOMPARE(plain.counts.fragmentsStored, kPixels);

    const FrameStats trimmed = render(FragmentMethodKind::TwoPass, scene, layerCamera(), positiveIndex());
    QCOMPARE(trimmed.methodStats.geometryPasses, 2);
    QCOMPARE(trimmed.counts.unresolvedPixels, kPixels);
    QCOMPARE(trimmed.counts.overflowPixels, kPixels);
    QCOMPARE(trimmed.counts.fragmentsLost, (kShallowLayers - 1) * kPixels);
    QCOMPARE(m_renderer->readColor().pixelColor(kWidth / 2, kHeight / 2), QColor(255, 0, 255));
}

namespace {

enum class FirstLayer { Empty, Decides, Unresolved };

// What two passes can know about a pixel, from the reference's walk: nothing to show, the
// answer is the span's first fragment, or the answer lies deeper (or nowhere) and the
// first fragment does not show it.
FirstLayer expectedFirstLayer(const PixelTrace& trace)
{
    if (trace.walk.walkEnd == trace.walk.walkBegin)
        return FirstLayer::Empty;
    return trace.walk.shownIndex == std::ptrdiff_t(trace.walk.walkBegin) ? FirstLayer::Decides : FirstLayer::Unresolved;
}

FirstLayer actualFirstLayer(const TrimPixel& p)
{
    if (p.unresolved)
        return FirstLayer::Unresolved;
    return p.covered() ? FirstLayer::Decides : FirstLayer::Empty;
}

// A float rasteriser may decide these pixels otherwise (the definitions of
// tests/support/trim_comparison.h): a close depth order, a pixel centre near an edge of
// the reference's shown triangle, or a silhouette (fragments in only part of the 3×3
// neighbourhood).
bool ambiguous(const ReferenceDiagnostics& d, int x, int y)
{
    const std::size_t i = d.index(x, y);
    if (d.depthMargin[i] < 1e-4 || d.edgeDistancePx[i] < 1.0 / 32.0)
        return true;
    bool some = false;
    bool none = false;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int nx = std::clamp(x + dx, 0, d.width - 1);
            const int ny = std::clamp(y + dy, 0, d.height - 1);
            (d.hitCount[d.index(nx, ny)] > 0 ? some : none) = true;
        }
    return some && none;
}

} // namespace

void TestPeelingMethods::twoPassOnASelfCrossingSurface_data()
{
    QTest::addColumn<glm::dvec3>("viewDirection");
    QTest::addColumn<bool>("clipped");
    QTest::newRow("from below") << glm::dvec3(0.2, 1.0, -1.0) << false;
    QTest::newRow("clipped through the middle") << glm::dvec3(-0.35, -0.45, -1.0) << true;
}

// The pushed sphere under the alternating border rule, seen through the finger: where
// the span's first fragment is a boundary two-pass shows exactly the reference's answer;
// where the reference's answer lies deeper, it flags the pixel unresolved.
void TestPeelingMethods::twoPassOnASelfCrossingSurface()
{
    QFETCH(glm::dvec3, viewDirection);
    QFETCH(bool, clipped);
    static const Scene scene = *makeDemoScene("pushed-sphere");
    const Bounds bounds = scene.worldBounds();
    Camera camera = fitCamera(bounds, double(kWidth) / kHeight, viewDirection);
    camera.eye = camera.target + 0.5 * (camera.eye - camera.target); // fill the image
    camera = withDepthRange(camera, bounds);
    TrimSettings settings;
    settings.rule = StaticRule::AlternatingBorder;
    if (clipped) // keeps the half beyond the centre
        settings.clip = ClipPlane{true, {0.0, 0.0, -1.0}, bounds.center().z};
    const ReferenceRenderer reference(scene);
    const ReferenceResult expected = reference.render(camera, kWidth, kHeight, settings);
    const FrameStats stats = render(FragmentMethodKind::TwoPass, scene, camera, settings);
    const TrimImage actual = m_renderer->readTrimImage();

    int counts[3] = {0, 0, 0};
    int flagged = 0;
    int wrong = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const TrimPixel& p = actual.at(x, y);
            flagged += p.unresolved ? 1 : 0;
            if (ambiguous(expected.diagnostics, x, y))
                continue;
            const FirstLayer want = expectedFirstLayer(reference.tracePixel(camera, kWidth, kHeight, x, y, settings));
            ++counts[int(want)];
            const TrimPixel& r = expected.trim.at(x, y);
            const bool sameAnswer =
                want != FirstLayer::Decides || (p.primitiveId == r.primitiveId && p.facing == r.facing);
            wrong += (actualFirstLayer(p) == want && sameAnswer && p.windingAtStart == r.windingAtStart) ? 0 : 1;
        }
    const int compared = counts[0] + counts[1] + counts[2];
    qInfo("%d compared pixels: %d decided by the first layer, %d unresolved, %d empty; %d differ", compared,
          counts[int(FirstLayer::Decides)], counts[int(FirstLayer::Unresolved)], counts[int(FirstLayer::Empty)], wrong);
    QVERIFY(counts[int(FirstLayer::Decides)] > compared / 10);
    QVERIFY(counts[int(FirstLayer::Unresolved)] > compared / 50);
    QVERIFY2(wrong <= compared / 1000, qPrintable(QString("%1 of %2 pixels differ").arg(wrong).arg(compared)));
    QCOMPARE(stats.counts.unresolvedPixels, std::uint64_t(flagged));
    QCOMPARE(stats.counts.overflowPixels, std::uint64_t(flagged));
}

QTEST_MAIN(TestPeelingMethods)
#include "tst_peeling_methods.moc"
