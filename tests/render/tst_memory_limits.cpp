// Frames beyond the GPU's limits or the user's memory budget (render/frame_limits.h,
// mfr/node_buffer.h, render/memory_fallback.h): they are refused with GpuMemoryError
// before anything is allocated — the message says what was asked, which limit and what
// to change —, the renderer keeps working afterwards, and the fallback chain leads from
// every method to methods that hold less, whose frames still agree with the CPU
// reference under a budget that refused the chosen one.
#include "render/gl/gl_error.h"
#include "gl_test_context.h"
#include "render/memory_fallback.h"
#include "method_check.h"
#include "render/trim_renderer.h"

#include "core/catalog/demo_scenes.h"
#include "core/trim/csg_expression.h"
#include "core/trim/reference_renderer.h"

#include <QtTest>

using namespace trimlab;
using namespace trimlab::render;

Q_DECLARE_METATYPE(trimlab::render::FragmentMethodKind)

namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;

// The message of the GpuMemoryError that rendering one frame throws; "" when none.
QString memoryErrorOf(TrimRenderer& renderer, const Camera& camera, const TrimSettings& settings, int width, int height)
{
    try {
        renderer.render(camera, settings, width, height);
    } catch (const GpuMemoryError& e) {
        return QString::fromUtf8(e.what());
    }
    return {};
}

} // namespace

class TestMemoryLimits : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void budgetRefusesEstimatedMethodsBeforeAllocating_data();
    void budgetRefusesEstimatedMethodsBeforeAllocating();
    void budgetRefusesCountedMethodsWhenTheyGrow_data();
    void budgetRefusesCountedMethodsWhenTheyGrow();
    void framesBeyondTheTextureLimitAreRefused();
    void fallbackChainEndsAndSavesMemory();
    void fallbackFrameAgreesWithTheReference();

private:
    [[nodiscard]] MethodParameters withBudget(std::size_t bytes) const
    {
        MethodParameters parameters;
        parameters.memoryBudgetBytes = bytes;
        return parameters;
    }

    std::unique_ptr<OffscreenGlContext> m_context;
    std::unique_ptr<TrimRenderer> m_renderer;
    Scene m_scene;
    Camera m_camera;
};

void TestMemoryLimits::initTestCase()
{
    TRIMLAB_INIT_GL_CONTEXT(m_context);
    m_renderer = std::make_unique<TrimRenderer>(m_context->context());
    m_scene = *makeDemoScene("pushed-sphere");
    m_renderer->setScene(m_scene);
    m_camera = fitCamera(m_scene.worldBounds(), double(kWidth) / kHeight);
}

void TestMemoryLimits::budgetRefusesEstimatedMethodsBeforeAllocating_data()
{
    QTest::addColumn<FragmentMethodKind>("method");
    for (const MethodInfo& info : fragmentMethods()) {
        m_renderer->setMethod(info.kind);
        if (m_renderer->estimateMethodBytes(kWidth, kHeight))
            QTest::newRow(info.id.data()) << info.kind;
    }
}

// A budget one byte below the estimate refuses the frame; the estimate itself passes.
void TestMemoryLimits::budgetRefusesEstimatedMethodsBeforeAllocating()
{
    QFETCH(FragmentMethodKind, method);
    m_renderer->setMethod(FragmentMethodKind::SBuffer); // never estimated: a fresh method object below
    m_renderer->setMethod(method);
    m_renderer->setParameters(MethodParameters{});
    const std::size_t estimate = *m_renderer->estimateMethodBytes(kWidth, kHeight);
    m_renderer->setParameters(withBudget(estimate - 1));
    const QString message = memoryErrorOf(*m_renderer, m_camera, TrimSettings{}, kWidth, kHeight);
    QVERIFY2(message.contains("budget"), qPrintable(message));
    QVERIFY2(message.contains("MB") && message.contains("160x120"), qPrintable(message));
    QVERIFY2(message.contains("Raise the budget"), qPrintable(message));
    // Refused before allocating: the method holds nothing.
    QCOMPARE(m_renderer->methodObject().stats().bytes, std::size_t(0));

    m_renderer->setParameters(withBudget(estimate));
    QCOMPARE(memoryErrorOf(*m_renderer, m_camera, TrimSettings{}, kWidth, kHeight), QString());
    QVERIFY(m_renderer->lastStats().counts.fragmentsInSpan > 0);
}

void TestMemoryLimits::budgetRefusesCountedMethodsWhenTheyGrow_data()
{
    QTest::addColumn<FragmentMethodKind>("method");
    QTest::newRow("s-buffer") << FragmentMethodKind::SBuffer;
    QTest::newRow("kplus-sbuffer") << FragmentMethodKind::KPlusSBuffer;
    QTest::newRow("abuffer-linked-list") << FragmentMethodKind::ABufferLinkedList;
}

// The counted methods know their storage only after counting: a budget below the frame's
// fragments refuses the node buffer; without a budget the same frame renders.
void TestMemoryLimits::budgetRefusesCountedMethodsWhenTheyGrow()
{
    QFETCH(FragmentMethodKind, method);
    m_renderer->setMethod(FragmentMethodKind::PeelingF2B); // a fresh method object below
    m_renderer->setMethod(method);
    m_renderer->setParameters(withBudget(4096)); // 512 fragments at most
    const QString message = memoryErrorOf(*m_renderer, m_camera, TrimSettings{}, kWidth, kHeight);
    QVERIFY2(message.contains("fragments"), qPrintable(message));
    QVERIFY2(message.contains("budget"), qPrintable(message));
    QVERIFY2(!message.contains("GL_MAX_SHADER_STORAGE_BLOCK_SIZE"), qPrintable(message));
    m_renderer->setParameters(MethodParameters{});
    QCOMPARE(memoryErrorOf(*m_renderer, m_camera, TrimSettings{}, kWidth, kHeight), QString());
    QVERIFY(m_renderer->lastStats().counts.fragmentsInSpan > 0);
}

void TestMemoryLimits::framesBeyondTheTextureLimitAreRefused()
{
    const int maxSide = m_renderer->capabilities().maxTextureSize;
    QVERIFY(maxSide > 0);
    m_renderer->setMethod(FragmentMethodKind::KPlusArray);
    m_renderer->setParameters(MethodParameters{});
    const QString message = memoryErrorOf(*m_renderer, m_camera, TrimSettings{}, maxSide + 1, 1);
    QVERIFY2(message.contains("GL_MAX_TEXTURE_SIZE"), qPrintable(message));
    QVERIFY2(message.contains(QString::number(maxSide)), qPrintable(message));
    // Nothing was changed: the next ordinary frame renders.
    QCOMPARE(memoryErrorOf(*m_renderer, m_camera, TrimSettings{}, kWidth, kHeight), QString());
}

// From every method the chain ends (no cycles), never passes a method the mode or the
// settings cannot run (CSG and the highlights need an inspection method), and each step
// holds no more memory at this view than the one before.
void TestMemoryLimits::fallbackChainEndsAndSavesMemory()
{
    for (const bool dynamic : {false, true}) {
        for (const bool inspection : {false, true}) {
            for (const MethodInfo& start : fragmentMethods()) {
                int steps = 0;
                for (auto method = memoryFallbackAfter(start.kind, dynamic, inspection); method;
                     method = memoryFallbackAfter(*method, dynamic, inspection)) {
                    QVERIFY2(++steps <= 3, start.id.data());
                    if (dynamic)
                        QVERIFY2(methodInfo(*method).dynamicRules, methodInfo(*method).id.data());
                    if (inspection)
                        QVERIFY2(methodInfo(*method).inspection, methodInfo(*method).id.data());
                }
            }
        }
    }
    TrimSettings csg;
    csg.csg.expression = *parseCsgExpression("0 - 1", nullptr);
    QVERIFY(needsInspectionMethod(csg));
    QVERIFY(!needsInspectionMethod(TrimSettings{}));
    TrimSettings xray;
    xray.transparency.enabled = true;
    QVERIFY(needsInspectionMethod(xray));
    // With CSG on, the S-buffer's fallback is the CPU still, not peeling's refusal.
    QCOMPARE(memoryFallbackAfter(FragmentMethodKind::SBuffer, false, true), std::nullopt);
    // The bounded arrays fall back to the S-buffer, which holds exactly the fragments.
    m_renderer->setMethod(FragmentMethodKind::KPlusArray);
    m_renderer->setParameters(MethodParameters{});
    m_renderer->render(m_camera, TrimSettings{}, kWidth, kHeight);
    const std::size_t kplusBytes = m_renderer->lastStats().methodStats.bytes;
    QCOMPARE(memoryFallbackAfter(FragmentMethodKind::KPlusArray, false), FragmentMethodKind::SBuffer);
    m_renderer->setMethod(FragmentMethodKind::SBuffer);
    m_renderer->render(m_camera, TrimSettings{}, kWidth, kHeight);
    const std::size_t sBufferBytes = m_renderer->lastStats().methodStats.bytes;
    QVERIFY2(sBufferBytes < kplusBytes, qPrintable(QString("%1 vs %2").arg(sBufferBytes).arg(kplusBytes)));
    QCOMPARE(memoryFallbackAfter(FragmentMethodKind::SBuffer, false), FragmentMethodKind::PeelingF2B);
    QCOMPARE(memoryFallbackAfter(FragmentMethodKind::PeelingF2B, false), std::nullopt);
    QCOMPARE(memoryFallbackAfter(FragmentMethodKind::SBuffer, true), std::nullopt);
}

// The k⁺-buffer refused by the budget; its fallback renders under that very budget and
// agrees with the CPU reference.
void TestMemoryLimits::fallbackFrameAgreesWithTheReference()
{
    m_renderer->setMethod(FragmentMethodKind::KPlusArray);
    m_renderer->setParameters(MethodParameters{});
    const std::size_t budget = *m_renderer->estimateMethodBytes(kWidth, kHeight) / 4;
    test::MethodCase testCase{
        QStringLiteral("fallback under budget"), m_camera, {}, withBudget(budget), kWidth, kHeight};
    m_renderer->setParameters(testCase.parameters);
    QVERIFY(!memoryErrorOf(*m_renderer, m_camera, testCase.settings, kWidth, kHeight).isEmpty());
    const ReferenceRenderer reference(m_scene);
    const ReferenceResult expected = reference.render(m_camera, kWidth, kHeight, testCase.settings);
    const FragmentMethodKind fallback = *memoryFallbackAfter(FragmentMethodKind::KPlusArray, false);
    QString summary;
    const auto failure =
        test::checkMethodAgainstReference(*m_renderer, fallback, testCase, reference, expected, &summary);
    qInfo("%s", qPrintable(summary));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
    QVERIFY(m_renderer->lastStats().methodStats.bytes <= budget);
}

QTEST_MAIN(TestMemoryLimits)
#include "tst_memory_limits.moc"
