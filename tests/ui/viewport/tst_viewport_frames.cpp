// The real main window's viewport paints without waiting for the GPU: a repaint issues
// the frame and returns, and the frame's numbers arrive from the event loop afterwards
// (frameRendered), with no call that can wait for the GPU in either — counted by the GL
// wrapper of the view's own context (render/gl/gl_functions.h). A readback then waits, so
// that the image and lastFrame() are the same frame, which agrees with the exact reference.
#include "demo_window.h"
#include "design_window.h"
#include "gl_test_context.h"

#include "render/gl/gl_functions.h"
#include "ui/viewport/viewport_widget.h"
#include "ui/window/main_window.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace trimlab;
using namespace trimlab::ui;

namespace {

constexpr QSize kViewportSize(192, 144);

/// The GPU waits counted so far in `viewport`'s context.
std::uint64_t gpuWaits(ViewportWidget& viewport)
{
    viewport.makeCurrent();
    const std::uint64_t waits = render::currentGlFunctions().gpuWaits();
    viewport.doneCurrent();
    return waits;
}

} // namespace

class TestViewportFrames : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void paintingNeverWaitsForTheGpu();

private:
    QTemporaryDir m_dir;
};

void TestViewportFrames::initTestCase()
{
    TRIMLAB_INIT_WIDGET_TEST();
    QVERIFY(m_dir.isValid());
}

void TestViewportFrames::paintingNeverWaitsForTheGpu()
{
    auto window = test::showDemoWindow(m_dir.filePath(QStringLiteral("frames.ini")), kViewportSize);
    ViewportWidget* viewport = window->viewport();
    QVERIFY(QTest::qWaitFor([&] { return viewport->lastFrame().has_value(); }, test::kDemoWaitMs));
    test::waitUntilViewIdle(*viewport);
    QCOMPARE(viewport->lastFrame()->stats.counts.fragmentsLost, std::uint64_t(0)); // no overflow readback

    for (int frame = 0; frame < 3; ++frame) {
        const std::uint64_t before = gpuWaits(*viewport);
        const std::uint64_t shown = viewport->lastFrame()->stats.serial;
        QSignalSpy arrived(viewport, &ViewportWidget::frameRendered);
        viewport->repaint();
        QCOMPARE(gpuWaits(*viewport), before); // the paint
        QVERIFY(arrived.wait(test::kDemoWaitMs));
        QCOMPARE(gpuWaits(*viewport), before); // the results, collected from the event loop
        QVERIFY(viewport->lastFrame()->stats.serial > shown);
    }
    const std::uint64_t before = gpuWaits(*viewport);
    const std::optional<QString> failure = test::lastFrameDisagreement(*window, QStringLiteral("viewport_frames"));
    QVERIFY2(!failure, qPrintable(failure.value_or(QString())));
    QVERIFY(gpuWaits(*viewport) > before); // the readback waited, as it must
}

QTEST_MAIN(TestViewportFrames)
#include "tst_viewport_frames.moc"
