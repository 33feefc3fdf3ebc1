// The buffer-based methods beyond what the method matrix checks: the S-buffer and
// K⁺B-SB allocate exactly the fragments they count, and those are the CPU reference's
// per-pixel hit counts (Σ f(p) and Σ min(f(p), k)); the S-buffer's image does not depend
// on its number of shared counters; AB_LL's regrowth renders the same image; AB_FP and
// K⁺B-SB flag overflow exactly where a pixel has more than k fragments; lists longer
// than the resolve's register array stay exact; a node buffer beyond the driver's
// storage limit is refused with a message.
//
// Silhouettes. The GPU snaps vertices to 1/256 px, so where a closed surface's silhouette
// passes within that distance of a pixel centre the rasteriser may place the pixel on the
// other side than the exact ray caster: the pixel then gains or loses the surface's two
// grazing fragments. A pixel is a *silhouette pixel* when one of its 8 neighbours has a
// different reference hit count; there the GPU count must lie within the counts of the
// reference's 3×3 neighbourhood, everywhere else it must be exact. Silhouette pixels that
// differ are counted and printed (2 of about 5,400 in the nested spheres at 200×150).
#include "render/gl/gl_capabilities.h"
#include "render/gl/gl_error.h"
#include "gl_test_context.h"
#include "render/mfr/abuffer_linked_list.h"
#include "render/mfr/kplus_s_buffer.h"
#include "render/mfr/node_buffer.h"
#include "render/mfr/resolve_budget.h"
#include "render/mfr/s_buffer.h"
#include "render/trim_renderer.h"

#include "core/scene/shape_generators.h"
#include "core/trim/reference_renderer.h"

#include <QtTest>

#include <algorithm>
#include <functional>
#include <numeric>

using namespace trimlab;
using namespace trimlab::render;

namespace {

constexpr int kWidth = 200;
constexpr int kHeight = 150;

// 17 nested spheres: 34 layers through the centre (as tst_method_matrix.cpp).
Scene nestedSpheres()
{
    TriangleMesh all;
    for (int i = 0; i < 17; ++i)
        appendMesh(all, makeIcosphere(glm::dvec3(0.0), 1.0 - 0.05 * i, 2));
    Scene scene;
    scene.objects.push_back({"nested spheres", all, glm::dmat4(1.0)});
    return scene;
}

// Submission slot s of the layered scene holds layer (s · 7919) mod layers (7919 is a
// prime that divides no layer count used here, so this permutes).
int layerAtSlot(int slot, int layers)
{
    return int((std::int64_t(slot) * 7919) % layers);
}
int layerOfPrimitive(int primitiveId, int layers)
{
    return layerAtSlot(primitiveId / 2, layers);
}

// `layers` quads at depths 1 + 0.001·i reaching far beyond the frustum, in shuffled
// order. The first `leading` layers are back-facing, the rest alternate front/back
// (`layers − leading` even). Seen from the eye the winding index at the near plane is
// then `leading` (the alternating ones cancel in pairs), and walking front to back it
// falls by one per back-facing layer: under the positive index rule every pixel shows
// layer `leading − 1`, back-facing.
Scene layeredScene(int layers, int leading)
{
    TriangleMesh mesh;
    for (int slot = 0; slot < layers; ++slot) {
        const int layer = layerAtSlot(slot, layers);
        const float depth = 1.0f + 0.001f * float(layer);
        const float s = 10.0f * depth;
        const auto base = static_cast<unsigned>(mesh.positions.size());
        mesh.positions.insert(mesh.positions.end(),
                              {{-s, -s, -depth}, {s, -s, -depth}, {s, s, -depth}, {-s, s, -depth}});
        const bool front = layer >= leading && (layer - leading) % 2 == 0;
        if (front) // counter-clockwise seen from the eye at the origin
            mesh.triangles.insert(mesh.triangles.end(), {{base, base + 1, base + 2}, {base, base + 2, base + 3}});
        else
            mesh.triangles.insert(mesh.triangles.end(), {{base, base + 2, base + 1}, {base, base + 3, base + 2}});
    }
    Scene scene;
    scene.objects.push_back({"layers", mesh, glm::dmat4(1.0)});
    return scene;
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

TrimSettings unclipped(StaticRule rule)
{
    TrimSettings settings;
    settings.rule = rule;
    settings.clip.enabled = false;
    return settings;
}

// Pixels where any field of the two trim images differs.
int differingPixels(const TrimImage& a, const TrimImage& b)
{
    int differing = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const TrimPixel& p = a.pixels[i];
        const TrimPixel& q = b.pixels[i];
        const bool same = p.primitiveId == q.primitiveId && p.objectId == q.objectId && p.facing == q.facing &&
                          p.windingAtStart == q.windingAtStart && p.viewDepth == q.viewDepth &&
                          p.overflowed == q.overflowed && p.unresolved == q.unresolved;
        differing += same ? 0 : 1;
    }
    return differing;
}

// Per-pixel GPU values against values expected from the reference's hit counts, exact
// away from silhouettes and within the 3×3 neighbourhood's range on them (file comment).
struct CountComparison {
    int silhouettePixels = 0;
    int differingOnSilhouettes = 0;
    int wrong = 0; ///< differ off a silhouette, or outside the neighbourhood's range on one
};

CountComparison compareWithReferenceCounts(const std::vector<std::uint32_t>& gpu, const ReferenceDiagnostics& reference,
                                           const std::function<std::int64_t(std::int32_t hits)>& expected)
{
    CountComparison result;
    for (int y = 0; y < reference.height; ++y) {
        for (int x = 0; x < reference.width; ++x) {
            const std::int32_t own = reference.hitCount[reference.index(x, y)];
            std::int64_t lo = expected(own);
            std::int64_t hi = lo;
            bool silhouette = false;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx;
                    const int ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= reference.width || ny >= reference.height)
                        continue;
                    const std::int32_t hits = reference.hitCount[reference.index(nx, ny)];
                    silhouette = silhouette || hits != own;
                    lo = std::min(lo, expected(hits));
                    hi = std::max(hi, expected(hits));
                }
            }
            const std::int64_t value = gpu[reference.index(x, y)];
            result.silhouettePixels += silhouette ? 1 : 0;
            result.differingOnSilhouettes += silhouette && value != expected(own) ? 1 : 0;
            result.wrong += (silhouette ? (value < lo || value > hi) : value != expected(own)) ? 1 : 0;
        }
    }
    qInfo("%d silhouette pixels, %d of them differ from the reference (within their neighbourhood's range)",
          result.silhouettePixels, result.differingOnSilhouettes);
    return result;
}

template <typename Method>
Method& currentMethod(TrimRenderer& renderer)
{
    return dynamic_cast<Method&>(renderer.methodObject());
}

} // namespace

Q_DECLARE_METATYPE(trimlab::render::FragmentMethodKind)

class TestBufferMethods : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void sBufferAllocatesExactlyTheReferenceFragments();
    void countedMethodsMatchTheReferenceWithoutSilhouettes_data();
    void countedMethodsMatchTheReferenceWithoutSilhouettes();
    void kplusSBufferAllocatesTheBoundedCounts();
    void sBufferImageIndependentOfSharedCounters();
    void linkedListRegrowthGivesTheSameImage();
    void overflowFlaggedExactlyBeyondK_data();
    void overflowFlaggedExactlyBeyondK();
    void listsLongerThanTheRegisterArrayStayExact_data();
    void listsLongerThanTheRegisterArrayStayExact();
    void listsBeyondTheLoopBudgetAreUnresolved_data();
    void listsBeyondTheLoopBudgetAreUnresolved();
    void nodeBufferBeyondTheStorageLimitIsRefused();

private:
    /// Renders the nested spheres with a fresh object of `method` (switching away first).
    void renderNested(FragmentMethodKind method, const MethodParameters& parameters);
    /// f(p) of the nested spheres as the S-buffer counts it.
    std::vector<std::uint32_t> gpuFragmentCounts();

    std::unique_ptr<OffscreenGlContext> m_context;
    std::unique_ptr<TrimRenderer> m_renderer;
    Scene m_nested;
    Camera m_camera;
    ReferenceResult m_reference; // no clip plane: hitCount is f(p)
};

void TestBufferMethods::initTestCase()
{
    TRIMLAB_INIT_GL_CONTEXT(m_context);
    m_renderer = std::make_unique<TrimRenderer>(m_context->context());
    m_nested = nestedSpheres();
    m_camera = fitCamera(m_nested.worldBounds(), double(kWidth) / kHeight);
    m_renderer->setScene(m_nested);
    m_reference =
        ReferenceRenderer(m_nested).render(m_camera, kWidth, kHeight, unclipped(StaticRule::AlternatingBorder));
}

void TestBufferMethods::renderNested(FragmentMethodKind method, const MethodParameters& parameters)
{
    m_renderer->setMethod(method == FragmentMethodKind::KPlusArray ? FragmentMethodKind::KPlusHeap
                                                                   : FragmentMethodKind::KPlusArray);
    m_renderer->setMethod(method);
    m_renderer->setParameters(parameters);
    m_renderer->render(m_camera, unclipped(StaticRule::AlternatingBorder), kWidth, kHeight);
}

std::vector<std::uint32_t> TestBufferMethods::gpuFragmentCounts()
{
    renderNested(FragmentMethodKind::SBuffer, {});
    return m_renderer->readOccupancy().value().held;
}

void TestBufferMethods::sBufferAllocatesExactlyTheReferenceFragments()
{
    renderNested(FragmentMethodKind::SBuffer, {});
    const auto& sbuffer = currentMethod<SBuffer>(*m_renderer);
    const std::vector<std::uint32_t> counts = m_renderer->readOccupancy().value().held;
    const std::uint64_t gpuTotal = std::accumulate(counts.begin(), counts.end(), std::uint64_t(0));
    QVERIFY(gpuTotal > 60000); // not vacuous: about 73k fragments, up to 34 per pixel
    QCOMPARE(sbuffer.countedTotal(), gpuTotal);
    QCOMPARE(sbuffer.nodeCapacity(), gpuTotal); // exactly the counted size
    const FrameCounts frame = m_renderer->lastStats().counts;
    QCOMPARE(frame.fragmentsInSpan, gpuTotal);
    QCOMPARE(frame.fragmentsStored, gpuTotal);
    QCOMPARE(frame.fragmentsLost, std::uint64_t(0));
    QCOMPARE(m_renderer->lastStats().methodStats.geometryPasses, 2);

    const CountComparison comparison =
        compareWithReferenceCounts(counts, m_reference.diagnostics, [](std::int32_t hits) { return hits; });
    QCOMPARE(comparison.wrong, 0);
    QVERIFY(comparison.differingOnSilhouettes * 100 <= comparison.silhouettePixels);
    const std::vector<std::int32_t>& hits = m_reference.diagnostics.hitCount;
    const auto referenceTotal = std::uint64_t(std::accumulate(hits.begin(), hits.end(), std::int64_t(0)));
    QVERIFY(std::max(gpuTotal, referenceTotal) - std::min(gpuTotal, referenceTotal) <=
            std::uint64_t(2 * 34 * comparison.differingOnSilhouettes));
}

void TestBufferMethods::countedMethodsMatchTheReferenceWithoutSilhouettes_data()
{
    QTest::addColumn<FragmentMethodKind>("method");
    QTest::addColumn<int>("k");
    QTest::newRow("s-buffer") << FragmentMethodKind::SBuffer << 16;
    QTest::newRow("kplus-sbuffer k=5") << FragmentMethodKind::KPlusSBuffer << 5;
    QTest::newRow("kplus-sbuffer k=40") << FragmentMethodKind::KPlusSBuffer << 40;
}

// 24 full-screen layers: no silhouette anywhere, so the allocation must equal the
// reference's count exactly: Σ f(p), or Σ min(f(p), k).
void TestBufferMethods::countedMethodsMatchTheReferenceWithoutSilhouettes()
{
    QFETCH(FragmentMethodKind, method);
    QFETCH(int, k);
    constexpr int kLayers = 24;
    constexpr int kSmallWidth = 64;
    constexpr int kSmallHeight = 48;
    const Scene scene = layeredScene(kLayers, 8);
    const ReferenceResult reference =
        ReferenceRenderer(scene).render(layerCamera(), kSmallWidth, kSmallHeight, unclipped(StaticRule::PositiveIndex));
    std::uint64_t expected = 0;
    for (std::int32_t hits : reference.diagnostics.hitCount)
        expected += std::uint64_t(method == FragmentMethodKind::SBuffer ? hits : std::min(hits, k));
    QCOMPARE(expected, std::uint64_t(std::min(kLayers, method == FragmentMethodKind::SBuffer ? kLayers : k)) *
                           kSmallWidth * kSmallHeight);

    TrimRenderer renderer(m_context->context());
    renderer.setScene(scene);
    renderer.setMethod(method);
    MethodParameters parameters;
    parameters.k = k;
    renderer.setParameters(parameters);
    renderer.render(layerCamera(), unclipped(StaticRule::PositiveIndex), kSmallWidth, kSmallHeight);
    std::uint64_t counted = 0;
    std::uint64_t capacity = 0;
    if (method == FragmentMethodKind::SBuffer) {
        counted = currentMethod<SBuffer>(renderer).countedTotal();
        capacity = currentMethod<SBuffer>(renderer).nodeCapacity();
    } else {
        counted = currentMethod<KPlusSBuffer>(renderer).countedTotal();
        capacity = currentMethod<KPlusSBuffer>(renderer).nodeCapacity();
    }
    QCOMPARE(counted, expected);
    QCOMPARE(capacity, expected);
    QCOMPARE(renderer.lastStats().counts.fragmentsStored, expected);
}

void TestBufferMethods::kplusSBufferAllocatesTheBoundedCounts()
{
    const std::vector<std::uint32_t> f = gpuFragmentCounts();
    for (int k : {1, 8, 16}) {
        MethodParameters parameters;
        parameters.k = k;
        renderNested(FragmentMethodKind::KPlusSBuffer, parameters);
        const auto& kplus = currentMethod<KPlusSBuffer>(*m_renderer);
        std::uint64_t bounded = 0;
        std::uint64_t beyond = 0;
        for (std::uint32_t n : f) {
            bounded += std::min(n, std::uint32_t(k));
            beyond += n > std::uint32_t(k) ? n - std::uint32_t(k) : 0;
        }
        QCOMPARE(kplus.countedTotal(), bounded);
        QCOMPARE(kplus.nodeCapacity(), bounded);
        const FrameCounts counts = m_renderer->lastStats().counts;
        QCOMPARE(counts.fragmentsStored, bounded);
        QCOMPARE(counts.fragmentsLost, beyond); // every fragment beyond a pixel's k nearest

        const std::vector<std::uint32_t> held = m_renderer->readOccupancy().value().held;
        const CountComparison comparison = compareWithReferenceCounts(
            held, m_reference.diagnostics, [k](std::int32_t hits) { return std::min(hits, k); });
        QCOMPARE(comparison.wrong, 0);
    }
}

void TestBufferMethods::sBufferImageIndependentOfSharedCounters()
{
    std::optional<TrimImage> first;
    std::optional<QImage> firstColor;
    for (int S : {1, 7, 1024}) {
        MethodParameters parameters;
        parameters.sharedCounters = S;
        renderNested(FragmentMethodKind::SBuffer, parameters);
        const TrimImage image = m_renderer->readTrimImage();
        const QImage color = m_renderer->readColor();
        QCOMPARE(m_renderer->lastStats().counts.fragmentsLost, std::uint64_t(0));
        if (!first) {
            first = image;
            firstColor = color;
            continue;
        }
        QCOMPARE(differingPixels(image, *first), 0);
        QVERIFY(color == *firstColor);
    }
}

void TestBufferMethods::linkedListRegrowthGivesTheSameImage()
{
    renderNested(FragmentMethodKind::ABufferLinkedList, {});
    auto& list = currentMethod<ABufferLinkedList>(*m_renderer);
    QCOMPARE(m_renderer->lastStats().methodStats.regrowths, 0); // the first guess holds the frame
    const TrimImage sized = m_renderer->readTrimImage();
    const std::uint64_t total = list.countedTotal();
    QVERIFY(total > 60000);

    list.setNodeCapacity(16, m_renderer->capabilities());
    m_renderer->render(m_camera, unclipped(StaticRule::AlternatingBorder), kWidth, kHeight);
    const FrameStats grown = m_renderer->lastStats();
    QCOMPARE(grown.methodStats.regrowths, 1);
    QCOMPARE(grown.methodStats.geometryPasses, 2);
    QCOMPARE(list.regrowthCount(), 1);
    QVERIFY(list.nodeCapacity() >= total);
    QCOMPARE(list.countedTotal(), total);
    // The counters are those of the frame that was shown, not of the one that overflowed.
    QCOMPARE(grown.counts.fragmentsLost, std::uint64_t(0));
    QCOMPARE(grown.counts.fragmentsStored, total);
    QCOMPARE(grown.counts.fragmentsInSpan, total);
    QCOMPARE(grown.counts.overflowPixels, std::uint64_t(0));
    QCOMPARE(differingPixels(m_renderer->readTrimImage(), sized), 0);

    m_renderer->render(m_camera, unclipped(StaticRule::AlternatingBorder), kWidth, kHeight);
    QCOMPARE(m_renderer->lastStats().methodStats.regrowths, 0);
    QCOMPARE(list.regrowthCount(), 1);
}

void TestBufferMethods::overflowFlaggedExactlyBeyondK_data()
{
    QTest::addColumn<FragmentMethodKind>("method");
    QTest::addColumn<int>("k");
    for (int k : {4, 10, 33}) {
        QTest::newRow(qPrintable(QString("abuffer-fixed k=%1").arg(k))) << FragmentMethodKind::ABufferFixed << k;
        QTest::newRow(qPrintable(QString("kplus-sbuffer k=%1").arg(k))) << FragmentMethodKind::KPlusSBuffer << k;
    }
}

// Flags and held counts against f(p): exactly against the S-buffer's count of the same
// view, and against the reference's hit counts as the file comment says.
void TestBufferMethods::overflowFlaggedExactlyBeyondK()
{
    QFETCH(FragmentMethodKind, method);
    QFETCH(int, k);
    const std::vector<std::uint32_t> f = gpuFragmentCounts();
    MethodParameters parameters;
    parameters.k = k;
    renderNested(method, parameters);
    const PixelOccupancy occupancy = m_renderer->readOccupancy().value();
    const TrimImage image = m_renderer->readTrimImage();
    int wrong = 0;
    std::uint64_t overflowing = 0;
    std::vector<std::uint32_t> flags(f.size());
    for (std::size_t i = 0; i < f.size(); ++i) {
        const bool beyond = f[i] > std::uint32_t(k);
        overflowing += beyond ? 1 : 0;
        flags[i] = occupancy.overflowed[i];
        wrong += (occupancy.overflowed[i] != 0) == beyond && image.pixels[i].overflowed == beyond &&
                         occupancy.held[i] == std::min(f[i], std::uint32_t(k))
                     ? 0
                     : 1;
    }
    QVERIFY(overflowing > 100); // not vacuous: the inner spheres give up to 34 layers
    QCOMPARE(wrong, 0);
    QCOMPARE(m_renderer->lastStats().counts.overflowPixels, overflowing);
    const CountComparison comparison =
        compareWithReferenceCounts(flags, m_reference.diagnostics, [k](std::int32_t hits) { return hits > k ? 1 : 0; });
    QCOMPARE(comparison.wrong, 0);
}

void TestBufferMethods::listsLongerThanTheRegisterArrayStayExact_data()
{
    QTest::addColumn<FragmentMethodKind>("method");
    QTest::newRow("s-buffer") << FragmentMethodKind::SBuffer;
    QTest::newRow("abuffer-linked-list") << FragmentMethodKind::ABufferLinkedList;
}

// 300 layers, beyond both resolves' 256 registers: the S-buffer sorts its region in the
// node buffer, AB_LL its list by relinking. The shown layer is the 270th nearest.
void TestBufferMethods::listsLongerThanTheRegisterArrayStayExact()
{
    QFETCH(FragmentMethodKind, method);
    constexpr int kLayers = 300;
    constexpr int kLeading = 270;
    constexpr int kSmallWidth = 32;
    constexpr int kSmallHeight = 24;
    static_assert(kLayers > SBuffer::kRegisterList && kLayers > ABufferLinkedList::kRegisterList);
    TrimRenderer renderer(m_context->context());
    renderer.setScene(layeredScene(kLayers, kLeading));
    renderer.setMethod(method);
    renderer.render(layerCamera(), unclipped(StaticRule::PositiveIndex), kSmallWidth, kSmallHeight);
    const TrimImage image = renderer.readTrimImage();
    const PixelOccupancy occupancy = renderer.readOccupancy().value();
    int wrong = 0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const TrimPixel& p = image.pixels[i];
        wrong += (occupancy.held[i] == kLayers && p.covered() && p.windingAtStart == kLeading && p.facing == -1 &&
                  layerOfPrimitive(p.primitiveId, kLayers) == kLeading - 1)
                     ? 0
                     : 1;
    }
    QCOMPARE(wrong, 0);
    const FrameCounts counts = renderer.lastStats().counts;
    QCOMPARE(counts.fragmentsStored, std::uint64_t(kLayers) * kSmallWidth * kSmallHeight);
    QCOMPARE(counts.unresolvedPixels, std::uint64_t(0));
    QCOMPARE(counts.overflowPixels, std::uint64_t(0));
}

void TestBufferMethods::listsBeyondTheLoopBudgetAreUnresolved_data()
{
    listsLongerThanTheRegisterArrayStayExact_data();
}

// 5000 layers: sorting them takes more loop iterations than llvmpipe lets a shader run
// (docs/llvmpipe-notes.md). Every pixel must be exact or reported unresolved, never
// wrong; under the llvmpipe budget (50,000) all are unresolved, elsewhere all exact.
void TestBufferMethods::listsBeyondTheLoopBudgetAreUnresolved()
{
    QFETCH(FragmentMethodKind, method);
    constexpr int kLayers = 5000;
    constexpr int kLeading = 4990;
    constexpr int kTinyWidth = 8;
    constexpr int kTinyHeight = 6;
    TrimRenderer renderer(m_context->context());
    renderer.setScene(layeredScene(kLayers, kLeading));
    renderer.setMethod(method);
    renderer.render(layerCamera(), unclipped(StaticRule::PositiveIndex), kTinyWidth, kTinyHeight);
    int exact = 0;
    int unresolved = 0;
    for (const TrimPixel& p : renderer.readTrimImage().pixels) {
        exact += p.covered() && p.windingAtStart == kLeading && p.facing == -1 &&
                         layerOfPrimitive(p.primitiveId, kLayers) == kLeading - 1 && !p.unresolved
                     ? 1
                     : 0;
        unresolved += !p.covered() && p.unresolved ? 1 : 0;
    }
    QCOMPARE(exact + unresolved, kTinyWidth * kTinyHeight);
    QCOMPARE(renderer.lastStats().counts.unresolvedPixels, std::uint64_t(unresolved));
    QCOMPARE(renderer.lastStats().counts.fragmentsLost, std::uint64_t(0));
    if (resolveLoopBudget(renderer.capabilities()) <= 50000)
        QCOMPARE(unresolved, kTinyWidth * kTinyHeight);
    else
        QCOMPARE(exact, kTinyWidth * kTinyHeight);
}

// The check every node buffer makes before allocating, against a driver limit of 1 KB
// (llvmpipe's real limit, 128 MB, would take a long frame to exceed).
void TestBufferMethods::nodeBufferBeyondTheStorageLimitIsRefused()
{
    GlCapabilities small = m_renderer->capabilities();
    small.maxShaderStorageBlockBytes = 1024;
    NodeBuffer nodes(currentGlFunctions(), 8, "S-buffer node buffer");
    QCOMPARE(nodes.maxNodes(small), std::uint64_t(128));
    nodes.reserve(128, small, 64, 48);
    QCOMPARE(nodes.capacity(), std::uint64_t(128));
    try {
        nodes.reserve(129, small, 64, 48);
        QFAIL("a node buffer above the storage limit was allocated");
    } catch (const GpuMemoryError& e) {
        const QString message = QString::fromUtf8(e.what());
        QVERIFY2(message.contains("129 fragments"), qPrintable(message));
        QVERIFY2(message.contains("MB"), qPrintable(message));
        QVERIFY2(message.contains("GL_MAX_SHADER_STORAGE_BLOCK_SIZE"), qPrintable(message));
        QVERIFY2(message.contains("bounded method"), qPrintable(message));
    }
    QCOMPARE(nodes.capacity(), std::uint64_t(128)); // the old buffer is kept
}

QTEST_MAIN(TestBufferMethods)
#include "tst_buffer_methods.moc"
