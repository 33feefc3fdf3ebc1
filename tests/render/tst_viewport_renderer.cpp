// The interactive view's renderer without the widget (render/viewport_renderer.h), on a
// real context: the content it keeps on the CPU — the scene, a pose, vertex colours, the
// dynamic rules' chain — goes into a new OpenGL context again and gives the same frame
// (what recovering from a GPU reset relies on), which agrees with the exact CPU reference
// of that content; out of memory it walks the fallback
// chain with a notice per step, down to the CPU still or, under the dynamic rules, a
// refusal; a new choice of parameters renders on the GPU again. The widget that carries
// this out is tested in ui.context_loss and ui.method_panel.
#include "gl_test_context.h"
#include "method_check.h"

#include "render/gl/gl_error.h"
#include "render/viewport_renderer.h"

#include "core/catalog/demo_scenes.h"
#include "core/catalog/fig8_13_history.h"
#include "core/timeline/frame_chain.h"
#include "core/trim/dynamic_reference_renderer.h"
#include "core/trim/reference_renderer.h"

#include <QtTest>

#include <memory>
#include <string>
#include <vector>

using namespace trimlab;
using namespace trimlab::render;

namespace {

constexpr QSize kSize(128, 96);

/// Pixels whose shown primitive, object, facing, winding or depth differ.
int differingPixels(const TrimImage& a, const TrimImage& b)
{
    if (a.width != b.width || a.height != b.height)
        return a.width * a.height + 1;
    int differ = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const TrimPixel& p = a.pixels[i];
        const TrimPixel& q = b.pixels[i];
        differ += p.primitiveId != q.primitiveId || p.objectId != q.objectId || p.facing != q.facing ||
                          p.windingAtStart != q.windingAtStart || p.viewDepth != q.viewDepth
                      ? 1
                      : 0;
    }
    return differ;
}

/// The frame in `view`'s renderer against `reference` (test/method_check.h criteria).
std::optional<QString> frameDisagreement(ViewportRenderer& view, const QString& name, const Camera& camera,
                                         const TrimSettings& settings, const ReferenceResult& reference)
{
    const test::MethodCase testCase{name, camera, settings, view.methodParameters(), kSize.width(), kSize.height()};
    return test::checkFrameAgainstReference(view.renderer(), testCase, reference, {});
}

int coveredPixels(const TrimImage& image)
{
    int covered = 0;
    for (const TrimPixel& p : image.pixels)
        covered += p.covered() ? 1 : 0;
    return covered;
}

} // namespace

class TestViewportRenderer : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void contentGoesIntoANewContext();
    void dynamicChainGoesIntoANewContext();
    void outOfMemoryWalksTheChainWithNotices();
    void dynamicRulesOutOfMemoryAreRefused();

private:
    /// Renders one frame and returns its trim image; `notices` receives the notices.
    TrimImage renderFrame(ViewportRenderer& view, const Camera& camera, std::vector<std::string>* notices = nullptr);

    std::unique_ptr<OffscreenGlContext> m_gl;
};

void TestViewportRenderer::initTestCase()
{
    TRIMLAB_INIT_GL_CONTEXT(m_gl);
}

TrimImage TestViewportRenderer::renderFrame(ViewportRenderer& view, const Camera& camera,
                                            std::vector<std::string>* notices)
{
    const bool rendered = view.render(camera, kSize, 0, [&](const std::string& notice) {
        if (notices)
            notices->push_back(notice);
    });
    if (!rendered || !view.lastFrame())
        return {};
    return view.renderer().readTrimImage();
}

// A pose (object 0 moved) and colours set before the first frame must reach the second
// context too: without them the frame differs, so the comparison sees a missed upload.
void TestViewportRenderer::contentGoesIntoANewContext()
{
    auto scene = std::make_shared<const Scene>(*makeDemoScene("pushed-sphere"));
    const Camera camera = fitCamera(scene->worldBounds(), double(kSize.width()) / kSize.height());
    ViewportRenderer view;
    view.setScene(scene);
    m_gl->makeCurrent();
    view.initialize(m_gl->context());
    const TrimImage unposed = renderFrame(view, camera);
    QVERIFY(coveredPixels(unposed) > 1000);

    std::vector<glm::vec3> pose = scene->objects.front().mesh.positions;
    for (glm::vec3& p : pose)
        p.x += 0.25f;
    view.showPose(pose);
    view.setVertexColors(std::vector<std::uint32_t>(pose.size(), 0xff2080ffu));
    const TrimImage posed = renderFrame(view, camera);
    QVERIFY(differingPixels(posed, unposed) > 100);
    const QImage posedColor = view.renderer().readColor();

    view.release(); // the context is lost; the content stays
    QVERIFY(!view.hasRenderer());
    OffscreenGlContext second;
    second.makeCurrent();
    view.initialize(second.context());
    const TrimImage again = renderFrame(view, camera);
    QCOMPARE(differingPixels(again, posed), 0);
    QVERIFY(view.renderer().readColor() == posedColor);
    // What was uploaded again is the content itself: the posed scene's exact reference.
    const ReferenceResult reference =
        ReferenceRenderer(*view.posedScene()).render(camera, kSize.width(), kSize.height(), TrimSettings{});
    const std::optional<QString> failure =
        frameDisagreement(view, QStringLiteral("viewport_renderer_posed"), camera, TrimSettings{}, reference);
    QVERIFY2(!failure, qPrintable(failure.value_or(QString())));
    view.release();
}

// Under the dynamic rules the chain's levels are uploaded anew in a new context.
void TestViewportRenderer::dynamicChainGoesIntoANewContext()
{
    const timeline::Timeline history = fig8_13NurbsHistory();
    const int last = history.frameCount() - 1;
    auto chain = std::make_shared<const DynamicChain>(timeline::frameChain(history, last, StaticRule::Parity));
    auto scene = std::make_shared<const Scene>(timeline::frameScene(history, last));
    const Camera camera = fitCamera(timeline::chainBounds(*chain), double(kSize.width()) / kSize.height());
    TrimSettings settings;
    settings.rule = StaticRule::Parity;
    ViewportRenderer view;
    view.setScene(scene);
    view.setTrimSettings(settings);
    view.setMethod(FragmentMethodKind::SBuffer);
    view.setDynamicChain(chain);
    m_gl->makeCurrent();
    view.initialize(m_gl->context());
    const TrimImage first = renderFrame(view, camera);
    QVERIFY(view.lastDynamicStats().has_value());
    QVERIFY(coveredPixels(first) > 500);
    view.release();
    OffscreenGlContext second;
    second.makeCurrent();
    view.initialize(second.context());
    const TrimImage again = renderFrame(view, camera);
    QVERIFY(view.lastDynamicStats().has_value());
    QCOMPARE(differingPixels(again, first), 0);
    const ReferenceResult reference =
        DynamicReferenceRenderer(*chain).render(camera, kSize.width(), kSize.height(), settings);
    const std::optional<QString> failure =
        frameDisagreement(view, QStringLiteral("viewport_renderer_dynamic"), camera, settings, reference);
    QVERIFY2(!failure, qPrintable(failure.value_or(QString())));
    view.release();
}

// A budget no method fits: every step of the chain is announced, then the CPU still; a
// choice without the budget renders on the GPU again.
void TestViewportRenderer::outOfMemoryWalksTheChainWithNotices()
{
    auto scene = std::make_shared<const Scene>(*makeDemoScene("pushed-sphere"));
    const Camera camera = fitCamera(scene->worldBounds(), double(kSize.width()) / kSize.height());
    ViewportRenderer view;
    view.setScene(scene);
    MethodParameters tiny;
    tiny.memoryBudgetBytes = 1;
    view.setMethodParameters(tiny);
    m_gl->makeCurrent();
    view.initialize(m_gl->context());
    std::vector<std::string> notices;
    QVERIFY(!view.render(camera, kSize, 0, [&](const std::string& notice) { notices.push_back(notice); }));
    QVERIFY(view.policy().showsCpuStill());
    QVERIFY(!view.lastFrame());
    // k⁺-buffer → S-buffer → F2B peeling → the CPU still: three notices.
    QCOMPARE(notices.size(), std::size_t(3));
    QVERIFY(notices.back().find("CPU reference") != std::string::npos);
    QCOMPARE(view.policy().chosenMethod(), FragmentMethodKind::KPlusArray);

    view.setMethodParameters(MethodParameters{});
    QVERIFY(!view.policy().showsCpuStill());
    QVERIFY(coveredPixels(renderFrame(view, camera, &notices)) > 1000);
    QCOMPARE(notices.size(), std::size_t(3));
    view.release();
}

void TestViewportRenderer::dynamicRulesOutOfMemoryAreRefused()
{
    const timeline::Timeline history = fig8_13NurbsHistory();
    const int last = history.frameCount() - 1;
    auto chain = std::make_shared<const DynamicChain>(timeline::frameChain(history, last, StaticRule::Parity));
    const Camera camera = fitCamera(timeline::chainBounds(*chain), double(kSize.width()) / kSize.height());
    ViewportRenderer view;
    view.setScene(std::make_shared<const Scene>(timeline::frameScene(history, last)));
    MethodParameters tiny;
    tiny.memoryBudgetBytes = 1;
    view.setMethodParameters(tiny);
    view.setDynamicChain(chain);
    m_gl->makeCurrent();
    view.initialize(m_gl->context());
    std::vector<std::string> notices;
    try {
        (void)view.render(camera, kSize, 0, [&](const std::string& notice) { notices.push_back(notice); });
        QFAIL("a frame no method fits rendered under the dynamic rules");
    } catch (const GpuMemoryError& e) {
        QVERIFY2(std::string(e.what()).find("No GPU method with the dynamic rules fits") != std::string::npos, e.what());
    }
    QCOMPARE(notices.size(), std::size_t(1)); // k⁺-buffer → S-buffer, then the refusal
    QVERIFY(!view.policy().showsCpuStill());
    view.release();
}

QTEST_MAIN(TestViewportRenderer)
#include "tst_viewport_renderer.moc"
