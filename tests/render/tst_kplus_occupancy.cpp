// The k+-buffer keeps exactly the k nearest fragments of every pixel and counts the
// winding index exactly, also where later triangles fully cover llvmpipe's tiles (the
// fragment-dropping trap of docs/llvmpipe-notes.md): 64 full-screen layers at known depths, submitted
// in a shuffled order, checked pixel by pixel.
#include "gl_test_context.h"
#include "render/mfr/kplus_buffer.h"
#include "render/trim_renderer.h"

#include <QtTest>

using namespace trimlab;
using namespace trimlab::render;

namespace {

constexpr int kLayers = 64;
constexpr int kWidth = 256;
constexpr int kHeight = 192;

double layerDepth(int layer)
{
    return 1.0 + 0.01 * layer;
}

// Layers 0..7 (nearest) are back-facing, the rest alternate front/back. Seen from the
// eye, the winding index at the near plane is then (8 + 28) - 28 = 8, and walking front
// to back it falls 8, 7, ..., 0: under the positive index rule the trim point is exactly
// layer 7, the 8th nearest fragment.
bool layerFrontFacing(int layer)
{
    return layer >= 8 && layer % 2 == 0;
}

// Submission slot s holds layer shuffled(s); 37 is coprime with 64, so this permutes.
int layerAtSlot(int slot)
{
    return (slot * 37) % kLayers;
}

Scene layeredScene()
{
    TriangleMesh mesh;
    for (int slot = 0; slot < kLayers; ++slot) {
        const int layer = layerAtSlot(slot);
        const float z = -float(layerDepth(layer));
        const float s = 10.0f * float(layerDepth(layer)); // far beyond the frustum
        const auto base = static_cast<unsigned>(mesh.positions.size());
        mesh.positions.insert(mesh.positions.end(), {{-s, -s, z}, {s, -s, z}, {s, s, z}, {-s, s, z}});
        if (layerFrontFacing(layer)) // counter-clockwise seen from the eye at the origin
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

int layerOfPrimitive(int primitiveId)
{
    return layerAtSlot(primitiveId / 2);
}

} // namespace

class TestKPlusOccupancy : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void keepsNearestKAndCountsExactly();
    void trimPointIsTheKthNearest();
    void trimBeyondKIsReportedUnresolved();
    void largeKHoldsEveryLayer();
    void clipPlaneStartsTheSpanBetweenLayers();
    void lockChoiceIsMadeAndReported();

private:
    void renderLayers(int k, const TrimSettings& settings);
    std::unique_ptr<OffscreenGlContext> m_context;
    std::unique_ptr<TrimRenderer> m_renderer;
};

void TestKPlusOccupancy::initTestCase()
{
    TRIMLAB_INIT_GL_CONTEXT(m_context);
    m_renderer = std::make_unique<TrimRenderer>(m_context->context());
    m_renderer->setScene(layeredScene());
}

void TestKPlusOccupancy::renderLayers(int k, const TrimSettings& settings)
{
    m_renderer->setK(k);
    m_renderer->render(layerCamera(), settings, kWidth, kHeight);
}

void TestKPlusOccupancy::keepsNearestKAndCountsExactly()
{
    TrimSettings settings;
    settings.trimEnabled = false;
    renderLayers(8, settings);
    const PixelOccupancy occupancy = m_renderer->readOccupancy().value();
    const TrimImage trim = m_renderer->readTrimImage();
    int wrong = 0;
    for (int i = 0; i < kWidth * kHeight; ++i) {
        const TrimPixel& p = trim.pixels[std::size_t(i)];
        const bool exact = occupancy.held[std::size_t(i)] == 8 && occupancy.overflowed[std::size_t(i)] == 1 &&
                           p.windingAtStart == 8 && p.covered() && layerOfPrimitive(p.primitiveId) == 0 &&
                           p.facing == -1;
        wrong += exact ? 0 : 1;
    }
    QCOMPARE(wrong, 0);
    const FrameCounts counts = m_renderer->lastStats().counts;
    QCOMPARE(counts.fragmentsInSpan, std::uint64_t(kLayers) * kWidth * kHeight);
    QCOMPARE(counts.overflowPixels, std::uint64_t(kWidth) * kHeight);
    QCOMPARE(counts.unresolvedPixels, std::uint64_t(0));
    QCOMPARE(counts.spinGiveUps, std::uint64_t(0));
}

void TestKPlusOccupancy::trimPointIsTheKthNearest()
{
    TrimSettings settings;
    settings.rule = StaticRule::PositiveIndex;
    renderLayers(8, settings);
    const TrimImage trim = m_renderer->readTrimImage();
    int wrong = 0;
    for (const TrimPixel& p : trim.pixels)
        wrong += (p.covered() && layerOfPrimitive(p.primitiveId) == 7 && p.facing == -1) ? 0 : 1;
    QCOMPARE(wrong, 0);
    QCOMPARE(m_renderer->lastStats().counts.unresolvedPixels, std::uint64_t(0));
}

void TestKPlusOccupancy::trimBeyondKIsReportedUnresolved()
{
    TrimSettings settings;
    settings.rule = StaticRule::PositiveIndex;
    renderLayers(7, settings);
    const TrimImage trim = m_renderer->readTrimImage();
    int covered = 0;
    for (const TrimPixel& p : trim.pixels)
        covered += p.covered() ? 1 : 0;
    QCOMPARE(covered, 0);
    QCOMPARE(m_renderer->lastStats().counts.unresolvedPixels, std::uint64_t(kWidth) * kHeight);
    // Unresolved pixels are painted magenta, never the background or a wrong surface.
    const QImage color = m_renderer->readColor();
    QCOMPARE(color.pixelColor(kWidth / 2, kHeight / 2), QColor(255, 0, 255));
}

void TestKPlusOccupancy::largeKHoldsEveryLayer()
{
    TrimSettings settings;
    settings.rule = StaticRule::PositiveIndex;
    renderLayers(kLayers, settings);
    const PixelOccupancy occupancy = m_renderer->readOccupancy().value();
    const TrimImage trim = m_renderer->readTrimImage();
    int wrong = 0;
    for (int i = 0; i < kWidth * kHeight; ++i) {
        const TrimPixel& p = trim.pixels[std::size_t(i)];
        wrong += (occupancy.held[std::size_t(i)] == kLayers && occupancy.overflowed[std::size_t(i)] == 0 &&
                  p.covered() && layerOfPrimitive(p.primitiveId) == 7)
                     ? 0
                     : 1;
    }
    QCOMPARE(wrong, 0);
    QCOMPARE(m_renderer->lastStats().counts.overflowPixels, std::uint64_t(0));
}

// A view-aligned plane between layers 3 and 4 keeping the far side: the span starts at
// the plane, where w = 4 (layers 4..7 back-facing, the rest cancelling), and positive
// index again shows layer 7.
void TestKPlusOccupancy::clipPlaneStartsTheSpanBetweenLayers()
{
    TrimSettings settings;
    settings.rule = StaticRule::PositiveIndex;
    settings.clip = ClipPlane{true, {0.0, 0.0, -1.0}, -0.5 * (layerDepth(3) + layerDepth(4))};
    renderLayers(8, settings);
    const PixelOccupancy occupancy = m_renderer->readOccupancy().value();
    const TrimImage trim = m_renderer->readTrimImage();
    int wrong = 0;
    for (int i = 0; i < kWidth * kHeight; ++i) {
        const TrimPixel& p = trim.pixels[std::size_t(i)];
        wrong += (occupancy.held[std::size_t(i)] == 8 && p.windingAtStart == 4 && p.covered() &&
                  layerOfPrimitive(p.primitiveId) == 7)
                     ? 0
                     : 1;
    }
    QCOMPARE(wrong, 0);
    QCOMPARE(m_renderer->lastStats().counts.fragmentsInSpan, std::uint64_t(kLayers - 4) * kWidth * kHeight);
}

// The critical section is chosen at run time from the context's extensions and reported
// with the frame; on llvmpipe (no GL_ARB_fragment_shader_interlock) the spin-lock runs.
void TestKPlusOccupancy::lockChoiceIsMadeAndReported()
{
    GlCapabilities withInterlock = m_context->capabilities();
    withInterlock.extensions.insert("GL_ARB_fragment_shader_interlock");
    GlCapabilities without = m_context->capabilities();
    without.extensions.remove("GL_ARB_fragment_shader_interlock");
    QCOMPARE(chooseKPlusLock(withInterlock, true), KPlusLock::InterlockArb);
    QCOMPARE(chooseKPlusLock(withInterlock, false), KPlusLock::SpinLock);
    QCOMPARE(chooseKPlusLock(without, true), KPlusLock::SpinLock);
    QVERIFY(kplusStoreDefines(KPlusLock::InterlockArb, true).contains("KPLUS_INTERLOCK_ARB"));
    QVERIFY(!kplusStoreDefines(KPlusLock::SpinLock, false).contains("KPLUS_INTERLOCK_ARB"));

    TrimSettings settings;
    renderLayers(8, settings);
    const bool driverHasInterlock = m_context->capabilities().hasExtension("GL_ARB_fragment_shader_interlock");
    const MethodStats& stats = m_renderer->lastStats().methodStats;
    QVERIFY(stats.usesLock);
    QCOMPARE(stats.interlock, driverHasInterlock);
    QCOMPARE(QString(lockDescription(stats)),
             driverHasInterlock ? QString("fragment shader interlock") : QString("spin-lock"));
    qInfo("lock on this driver: %s", lockDescription(stats));
}

QTEST_MAIN(TestKPlusOccupancy)
#include "tst_kplus_occupancy.moc"
