// A GPU reset in the real main window (ViewportWidget::recoverFromContextLoss, which
// paintGL calls when the renderer reports GlContextLostError or Qt marks the context
// invalid). The driver's notification cannot be caused on purpose here, so the test
// enters where the notification would, and everything after it is real: the view drops
// its OpenGL context, Qt destroys it and creates a new one, the renderer is built again
// and the scene uploaded again. The frame after the reset must be the frame before it,
// byte for byte, and agree with the exact CPU reference; the status bar says what
// happened. A second reset before any frame succeeded moves to the next method of the
// fallback chain, and choosing the method again tries it again.
#include "demo_window.h"
#include "design_window.h"
#include "gl_test_context.h"

#include "render/gl/context_reset.h"
#include "ui/window/main_window.h"
#include "ui/render_panel/render_panel.h"
#include "ui/viewport/viewport_widget.h"

#include <QOpenGLContext>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>

using namespace trimlab;
using namespace trimlab::ui;
using trimlab::test::kWaitMs;

namespace {

constexpr QSize kViewportSize(192, 144);

QString resetMessage(render::ContextReset reset)
{
    return QString::fromStdString(render::contextResetMessage(reset));
}

} // namespace

class TestContextLoss : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void resetRecreatesTheContextAndTheSameFrame();
    void secondResetInARowFallsBackToALeanerMethod();

private:
    [[nodiscard]] std::unique_ptr<MainWindow> showWindow(const QString& settingsName)
    {
        return test::showDemoWindow(m_dir.filePath(settingsName + QStringLiteral(".ini")), kViewportSize);
    }
    [[nodiscard]] static bool waitForFrameOnContext(ViewportWidget& viewport, int contexts,
                                                    render::FragmentMethodKind method);

    QTemporaryDir m_dir;
};

void TestContextLoss::initTestCase()
{
    TRIMLAB_INIT_WIDGET_TEST();
    QVERIFY(m_dir.isValid());
}

// A frame rendered with `method` on the view's `contexts`-th context.
bool TestContextLoss::waitForFrameOnContext(ViewportWidget& viewport, int contexts, render::FragmentMethodKind method)
{
    return QTest::qWaitFor(
        [&] {
            return viewport.contextsInitialized() == contexts && viewport.lastFrame() &&
                   viewport.lastFrame()->stats.method == method;
        },
        kWaitMs);
}

void TestContextLoss::resetRecreatesTheContextAndTheSameFrame()
{
    auto window = showWindow(QStringLiteral("reset"));
    ViewportWidget* viewport = window->viewport();
    const render::FragmentMethodKind chosen = viewport->method();
    const int contexts = viewport->contextsInitialized();
    QVERIFY(contexts >= 1);
    QVERIFY(waitForFrameOnContext(*viewport, contexts, chosen));
    test::waitUntilViewIdle(*viewport);
    const QImage before = viewport->readColorImage();
    QVERIFY(!before.isNull());

    QSignalSpy destroyed(viewport->context(), &QOpenGLContext::aboutToBeDestroyed);
    QSignalSpy lost(viewport, &ViewportWidget::contextLost);
    viewport->recoverFromContextLoss(resetMessage(render::ContextReset::Innocent));
    QVERIFY(!viewport->lastFrame()); // the old frame's images went with the context
    QCOMPARE(lost.count(), 1);
    QVERIFY(waitForFrameOnContext(*viewport, contexts + 1, chosen));
    QCOMPARE(destroyed.count(), 1); // Qt really dropped the old context
    QVERIFY(viewport->errorMessage().isEmpty());
    QCOMPARE(viewport->effectiveMethod(), chosen); // one reset is not the method's fault

    const QImage after = viewport->readColorImage();
    QCOMPARE(after.size(), before.size());
    QVERIFY(after == before);
    const auto failure = test::lastFrameDisagreement(*window, QStringLiteral("after-reset"));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");

    const QString message = lost.front().front().toString();
    QVERIFY2(message.contains(QStringLiteral("another application")) &&
                 message.contains(QStringLiteral("re-created the OpenGL context")),
             qPrintable(message));
    QVERIFY2(QTest::qWaitFor([&] { return window->statusBar()->currentMessage() == message; }, kWaitMs),
             qPrintable(window->statusBar()->currentMessage()));
}

// Two resets with no frame between blame the method (e.g. a frame long enough to trip the
// driver's watchdog): the view renders with the next method of the memory fallback chain
// and says why; choosing the method again tries it again.
void TestContextLoss::secondResetInARowFallsBackToALeanerMethod()
{
    auto window = showWindow(QStringLiteral("repeated"));
    ViewportWidget* viewport = window->viewport();
    const render::FragmentMethodKind chosen = viewport->method();
    QCOMPARE(chosen, render::FragmentMethodKind::KPlusArray); // the default, whose fallback is the S-buffer
    const int contexts = viewport->contextsInitialized();
    QVERIFY(waitForFrameOnContext(*viewport, contexts, chosen));

    QSignalSpy lost(viewport, &ViewportWidget::contextLost);
    QSignalSpy fallback(viewport, &ViewportWidget::memoryFallback);
    const QString guilty = resetMessage(render::ContextReset::Guilty);
    viewport->recoverFromContextLoss(guilty);
    viewport->recoverFromContextLoss(guilty); // before any frame on the new context
    QCOMPARE(lost.count(), 1);
    QCOMPARE(fallback.count(), 1);
    const QString message = fallback.front().front().toString();
    QVERIFY2(message.contains(QStringLiteral("happened again")) && message.contains(QStringLiteral("S-buffer")),
             qPrintable(message));
    QVERIFY(waitForFrameOnContext(*viewport, contexts + 2, render::FragmentMethodKind::SBuffer));
    QCOMPARE(viewport->method(), chosen); // the user's choice is kept
    QCOMPARE(viewport->effectiveMethod(), render::FragmentMethodKind::SBuffer);
    const auto failure = test::lastFrameDisagreement(*window, QStringLiteral("after-second-reset"));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");

    // A successful frame clears the count: the next single reset keeps the S-buffer.
    viewport->recoverFromContextLoss(guilty);
    QVERIFY(waitForFrameOnContext(*viewport, contexts + 3, render::FragmentMethodKind::SBuffer));
    QCOMPARE(lost.count(), 2);
    QCOMPARE(fallback.count(), 1);

    viewport->setMethod(chosen);
    QVERIFY(waitForFrameOnContext(*viewport, contexts + 3, chosen));
}

QTEST_MAIN(TestContextLoss)
#include "tst_context_loss.moc"
