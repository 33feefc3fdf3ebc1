// The multi-fragment method as a user picks it: the method combo box (every method of the
// build, none named here), the k and S controls that follow the method, the overflow
// advice of the Frame statistics dock, "Measure all methods" and the persisted choice.
// Every frame a method renders is checked against the exact CPU reference with the
// viewport's own camera, size and settings.
#include "demo_window.h"
#include "gl_test_context.h"
#include "named_child.h"
#include "test_paths.h"

#include "ui/render_panel/frame_stats_panel.h"
#include "render/frame_times.h"
#include "ui/window/main_window.h"
#include "ui/render_panel/render_workspace.h"
#include "ui/render_panel/method_survey.h"
#include "ui/render_panel/method_timing_chart.h"
#include "ui/render_panel/method_timing_panel.h"
#include "ui/render_panel/overflow_advice.h"
#include "ui/render_panel/render_panel.h"
#include "ui/render_panel/render_settings_store.h"
#include "ui/viewport/viewport_widget.h"

#include "render/rgba_qimage.h"

#include <QDockWidget>
#include <QScrollArea>
#include <QScrollBar>
#include <QWheelEvent>
#include <QApplication>
#include <QtTest>

#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QToolButton>

using namespace trimlab;
using namespace trimlab::ui;
using trimlab::test::child;

namespace {

constexpr QSize kViewportSize(256, 192);
constexpr int kWaitMs = test::kDemoWaitMs;

bool frameOverflowed(const ViewportFrame& frame)
{
    return frame.stats.counts.unresolvedPixels > 0 || frame.stats.counts.fragmentsLost > 0;
}

} // namespace

class TestMethodPanel : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void comboSwitchesTheRendererMethod();
    void parameterControlsFollowTheMethod();
    void overflowAdviceRaisesKOrSwitches();
    void measureAllMethodsDrawsOneBarPerMethod();
    void methodChoicesRoundTrip();
    void storedMethodFallsBack();
    void overflowAdviceRules();
    void frameTimesUseGpuOnlyWhenEveryFrameHasOne();
    void memoryBudgetFallsBackToLeanerMethods();
    void wheelScrollsThePanelNotItsControls();

private:
    [[nodiscard]] std::unique_ptr<MainWindow> showWindow(const QString& settingsName)
    {
        return test::showDemoWindow(m_dir.filePath(settingsName + QStringLiteral(".ini")), kViewportSize);
    }
    [[nodiscard]] static bool waitForFrame(MainWindow& window, const std::function<bool(const ViewportFrame&)>& ready);
    [[nodiscard]] static std::optional<QString> disagreement(MainWindow& window, const QString& name)
    {
        return test::lastFrameDisagreement(window, name);
    }

    QTemporaryDir m_dir;
};

void TestMethodPanel::initTestCase()
{
    TRIMLAB_INIT_WIDGET_TEST();
    QVERIFY(m_dir.isValid());
}

bool TestMethodPanel::waitForFrame(MainWindow& window, const std::function<bool(const ViewportFrame&)>& ready)
{
    return QTest::qWaitFor(
        [&] {
            const auto& frame = window.viewport()->lastFrame();
            return frame && ready(*frame);
        },
        kWaitMs);
}

// Down-arrow through the combo box: each step re-renders with that method, and the frame
// agrees with the CPU reference.
void TestMethodPanel::comboSwitchesTheRendererMethod()
{
    auto window = showWindow(QStringLiteral("combo"));
    auto* combo = child<QComboBox>(window.get(), "methodComboBox");
    QVERIFY(combo);
    const std::vector<render::MethodInfo>& methods = render::fragmentMethods();
    QCOMPARE(combo->count(), int(methods.size()));
    QCOMPARE(combo->currentIndex(), 0);
    QVERIFY(waitForFrame(*window, [&](const ViewportFrame& f) { return f.stats.method == methods.front().kind; }));
    for (std::size_t i = 0; i < methods.size(); ++i) {
        if (i > 0)
            QTest::keyClick(combo, Qt::Key_Down);
        const render::FragmentMethodKind kind = methods[i].kind;
        QCOMPARE(combo->currentIndex(), int(i));
        QCOMPARE(window->viewport()->method(), kind);
        QVERIFY(waitForFrame(*window, [&](const ViewportFrame& f) { return f.stats.method == kind; }));
        const auto failure = disagreement(*window, QString::fromLatin1(methods[i].id.data()) + "-combo");
        QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
        auto* statsMethod = child<QLabel>(window.get(), "statsMethodLabel");
        QVERIFY(statsMethod && statsMethod->text() == QString::fromUtf8(methods[i].displayName.data()));
    }
}

// k and S are enabled exactly for the methods that use them; the memory label always
// says something once the renderer exists.
void TestMethodPanel::parameterControlsFollowTheMethod()
{
    auto window = showWindow(QStringLiteral("parameters"));
    QVERIFY(waitForFrame(*window, [](const ViewportFrame&) { return true; }));
    auto* combo = child<QComboBox>(window.get(), "methodComboBox");
    auto* k = child<QSpinBox>(window.get(), "kSpinBox");
    auto* shared = child<QSpinBox>(window.get(), "sharedCountersSpinBox");
    auto* memory = child<QLabel>(window.get(), "kMemoryLabel");
    QVERIFY(combo && k && shared && memory);
    QTest::keyClick(combo, Qt::Key_Home);
    for (std::size_t i = 0; i < render::fragmentMethods().size(); ++i) {
        const render::MethodInfo& info = render::fragmentMethods()[i];
        if (i > 0)
            QTest::keyClick(combo, Qt::Key_Down);
        QCOMPARE(window->viewport()->method(), info.kind);
        QCOMPARE(k->isEnabled(), info.usesK);
        QCOMPARE(shared->isEnabled(), info.usesSharedCounters);
        QVERIFY2(combo->itemData(combo->currentIndex(), Qt::ToolTipRole)
                     .toString()
                     .contains(info.bounded ? QStringLiteral("Capacity-bounded") : QStringLiteral("Unbounded")),
                 info.id.data());
        const MemoryEstimate estimate = window->viewport()->memoryEstimate();
        QVERIFY(estimate.available);
        QVERIFY2(
            memory->text().contains(estimate.bytes ? QStringLiteral("MB") : QStringLiteral("depends on the scene")),
            qPrintable(memory->text()));
    }
}

// k = 1 makes a bounded method overflow: the panel and the status bar say so, "Raise k"
// (pressed until the frame no longer overflows) removes it, and "Switch to" an unbounded
// method renders without overflow and agrees with the reference.
void TestMethodPanel::overflowAdviceRaisesKOrSwitches()
{
    auto window = showWindow(QStringLiteral("overflow"));
    auto* k = child<QSpinBox>(window.get(), "kSpinBox");
    QVERIFY(k && k->isEnabled());
    QTest::keyClick(k, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(k, QStringLiteral("1"));
    QTest::keyClick(k, Qt::Key_Return);
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) { return f.k == 1; }));
    QVERIFY2(frameOverflowed(*window->viewport()->lastFrame()), "k = 1 does not overflow the demo");
    auto* warning = child<QLabel>(window.get(), "overflowWarningLabel");
    auto* raise = child<QPushButton>(window.get(), "raiseKButton");
    auto* switchMethod = child<QToolButton>(window.get(), "switchMethodButton");
    auto* statusLabel = child<QLabel>(window.get(), "unresolvedLabel");
    QVERIFY(warning && raise && switchMethod && statusLabel);
    QVERIFY(warning->isVisibleTo(window.get()));
    QVERIFY(!statusLabel->styleSheet().isEmpty()); // highlighted in the status bar
    QVERIFY(raise->isVisibleTo(window.get()));
    QCOMPARE(raise->text(),
             QStringLiteral("Raise k to %1").arg(*window->renderWorkspace()->statsPanel()->advice().raiseKTo));
    QTest::qWait(100); // let the docks' layouts settle before the screenshot
    const QString shot = QString::fromStdString((test::outputDir() / "overflow-advice.png").string());
    QVERIFY(window->grab().save(shot));
    qInfo("screenshot: %s", qPrintable(shot));

    for (int presses = 0; presses < 8 && frameOverflowed(*window->viewport()->lastFrame()); ++presses) {
        const int target = *window->renderWorkspace()->statsPanel()->advice().raiseKTo;
        QTest::mouseClick(raise, Qt::LeftButton);
        QCOMPARE(k->value(), target);
        QVERIFY(waitForFrame(*window, [&](const ViewportFrame& f) { return f.k == target; }));
    }
    QVERIFY(!frameOverflowed(*window->viewport()->lastFrame()));
    QVERIFY(!warning->isVisibleTo(window.get()));
    QVERIFY(statusLabel->styleSheet().isEmpty());

    // Back to k = 1, then the unbounded remedy (when this build has an unbounded method).
    window->viewport()->setK(1);
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) { return f.k == 1 && frameOverflowed(f); }));
    const OverflowAdvice advice = window->renderWorkspace()->statsPanel()->advice();
    QCOMPARE(switchMethod->isVisibleTo(window.get()), !advice.unboundedMethods.empty());
    if (advice.unboundedMethods.empty())
        return;
    const render::FragmentMethodKind unbounded = advice.unboundedMethods.front();
    QVERIFY(!render::methodInfo(unbounded).bounded);
    QTest::mouseClick(switchMethod, Qt::LeftButton, {}, QPoint(8, switchMethod->height() / 2));
    QVERIFY(waitForFrame(*window, [&](const ViewportFrame& f) { return f.stats.method == unbounded; }));
    QCOMPARE(window->renderWorkspace()->panel()->renderChoices().method, unbounded);
    QVERIFY(!frameOverflowed(*window->viewport()->lastFrame()));
    QVERIFY(!warning->isVisibleTo(window.get()));
    const auto failure = disagreement(*window, QStringLiteral("switched-to-unbounded"));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
}

// One bar per method of the build, each with a time or a reason; the survey reports
// progress, and afterwards the view renders with the chosen method again.
void TestMethodPanel::measureAllMethodsDrawsOneBarPerMethod()
{
    auto window = showWindow(QStringLiteral("measure"));
    QVERIFY(waitForFrame(*window, [](const ViewportFrame&) { return true; }));
    const render::FragmentMethodKind chosen = window->viewport()->method();
    MethodTimingPanel* panel = window->renderWorkspace()->timingPanel();
    panel->setFramesPerMethod(1);
    auto* button = child<QPushButton>(window.get(), "measureAllButton");
    QVERIFY(button);
    QSignalSpy progress(panel->survey(), &MethodSurvey::progress);
    QSignalSpy finished(panel->survey(), &MethodSurvey::finished);
    QTest::mouseClick(button, Qt::LeftButton);
    QVERIFY(panel->survey()->isRunning());
    QCOMPARE(button->text(), QStringLiteral("Cancel"));
    QVERIFY(finished.wait(kWaitMs));
    const int methods = int(render::fragmentMethods().size());
    QCOMPARE(progress.size(), methods + 1);
    QCOMPARE(progress.last().at(0).toInt(), methods);
    QCOMPARE(button->text(), QStringLiteral("Measure all methods"));
    const std::vector<MethodTimingChart::Bar>& bars = panel->chart()->bars();
    QCOMPARE(int(bars.size()), methods);
    for (std::size_t i = 0; i < bars.size(); ++i) {
        const render::MethodInfo& info = render::fragmentMethods()[i];
        QCOMPARE(bars[i].label, QString::fromUtf8(info.displayName.data()));
        QVERIFY2(bars[i].milliseconds || !bars[i].toolTip.isEmpty(), info.id.data());
        if (bars[i].milliseconds)
            QVERIFY(*bars[i].milliseconds > 0.0);
        QCOMPARE(bars[i].highlighted, info.kind == chosen);
    }
    QVERIFY(!panel->chart()->grab().isNull());
    QVERIFY(waitForFrame(*window, [&](const ViewportFrame& f) { return f.stats.method == chosen; }));
    const auto failure = disagreement(*window, QStringLiteral("after-measuring"));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
}

// Method, k and S chosen with the keyboard persist into a new window and its renderer.
void TestMethodPanel::methodChoicesRoundTrip()
{
    const QString settings = QStringLiteral("round-trip");
    const std::vector<render::MethodInfo>& methods = render::fragmentMethods();
    const auto withS =
        std::find_if(methods.begin(), methods.end(), [](const render::MethodInfo& m) { return m.usesSharedCounters; });
    {
        auto window = showWindow(settings);
        auto* combo = child<QComboBox>(window.get(), "methodComboBox");
        auto* k = child<QSpinBox>(window.get(), "kSpinBox");
        auto* shared = child<QSpinBox>(window.get(), "sharedCountersSpinBox");
        QVERIFY(combo && k && shared);
        QTest::keyClick(k, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(k, QStringLiteral("24"));
        QTest::keyClick(k, Qt::Key_Return);
        if (withS != methods.end()) {
            combo->setCurrentIndex(int(withS - methods.begin()));
            QTest::keyClick(shared, Qt::Key_A, Qt::ControlModifier);
            QTest::keyClicks(shared, QStringLiteral("64"));
            QTest::keyClick(shared, Qt::Key_Return);
            QCOMPARE(window->viewport()->methodParameters().sharedCounters, 64);
        }
        QTest::keyClick(combo, Qt::Key_End);
        QCOMPARE(window->viewport()->method(), methods.back().kind);
        QCOMPARE(window->viewport()->k(), 24);
        window->close();
    }
    auto window = showWindow(settings);
    const RenderChoices restored = window->renderWorkspace()->panel()->renderChoices();
    QCOMPARE(restored.method, methods.back().kind);
    QCOMPARE(restored.k, 24);
    QCOMPARE(restored.sharedCounters, withS != methods.end() ? 64 : render::MethodParameters{}.sharedCounters);
    QCOMPARE(window->viewport()->method(), methods.back().kind);
    QVERIFY(waitForFrame(*window, [&](const ViewportFrame& f) { return f.stats.method == methods.back().kind; }));
}

// A stored method this build does not have, or an S out of range, falls back to the
// first-start choice (field by field); a stored valid method is kept.
void TestMethodPanel::storedMethodFallsBack()
{
    const QString path = m_dir.filePath(QStringLiteral("fallback.ini"));
    {
        QSettings settings(path, QSettings::IniFormat);
        settings.setValue(QStringLiteral("render/method"), QStringLiteral("no-such-method"));
        settings.setValue(QStringLiteral("render/sharedCounters"), 0);
        settings.setValue(QStringLiteral("render/k"), 7);
    }
    {
        const QSettings settings(path, QSettings::IniFormat);
        const RenderChoices loaded = loadRenderChoices(settings);
        QCOMPARE(loaded.method, firstStartRenderChoices().method);
        QCOMPARE(loaded.sharedCounters, firstStartRenderChoices().sharedCounters);
        QCOMPARE(loaded.k, 7);
    }
    for (const render::MethodInfo& info : render::fragmentMethods()) {
        RenderChoices choices = firstStartRenderChoices();
        choices.method = info.kind;
        choices.sharedCounters = 333;
        QSettings settings(path, QSettings::IniFormat);
        saveRenderChoices(settings, choices);
        const RenderChoices loaded = loadRenderChoices(settings);
        QCOMPARE(loaded.method, info.kind);
        QCOMPARE(loaded.sharedCounters, 333);
    }
}

// The advice as a pure function, with numbers derived by hand.
void TestMethodPanel::overflowAdviceRules()
{
    const auto array = render::FragmentMethodKind::KPlusArray; // bounded, uses k (always in the build)
    render::MethodParameters parameters;
    parameters.k = 4;
    render::FrameCounts clean;
    clean.fragmentsInSpan = 100;
    QVERIFY(!adviseOnOverflow(array, clean, parameters, std::nullopt).overflowing);

    render::FrameCounts lost = clean;
    lost.fragmentsLost = 12;
    lost.overflowPixels = 3;
    // The deepest pixel counted 10 > k: raise to exactly 10.
    OverflowAdvice advice = adviseOnOverflow(array, lost, parameters, 10u);
    QVERIFY(advice.overflowing);
    QCOMPARE(advice.raiseKTo, std::optional<int>(10));
    QVERIFY(advice.raiseKHoldsDeepestPixel);
    QVERIFY(advice.message.contains(QStringLiteral("k = 4")));
    // A count capped at k says nothing about the depth: double k.
    advice = adviseOnOverflow(array, lost, parameters, 4u);
    QCOMPARE(advice.raiseKTo, std::optional<int>(8));
    QVERIFY(!advice.raiseKHoldsDeepestPixel);
    // Deeper than the largest k: raise to the largest k, which still cannot hold it.
    advice = adviseOnOverflow(array, lost, parameters, 500u);
    QCOMPARE(advice.raiseKTo, std::optional<int>(render::MethodParameters::kMaxK));
    QVERIFY(!advice.raiseKHoldsDeepestPixel);
    parameters.k = render::MethodParameters::kMaxK;
    QVERIFY(!adviseOnOverflow(array, lost, parameters, 500u).raiseKTo);

    // Unresolved pixels alone also count; the unbounded methods are offered in menu order.
    render::FrameCounts unresolved = clean;
    unresolved.unresolvedPixels = 1;
    advice = adviseOnOverflow(array, unresolved, parameters, std::nullopt);
    QVERIFY(advice.overflowing);
    std::vector<render::FragmentMethodKind> unbounded;
    for (const render::MethodInfo& info : render::fragmentMethods())
        if (!info.bounded)
            unbounded.push_back(info.kind);
    QCOMPARE(advice.unboundedMethods, unbounded);
}

void TestMethodPanel::frameTimesUseGpuOnlyWhenEveryFrameHasOne()
{
    render::FrameTimes times;
    QCOMPARE(times.medianMilliseconds(), 0.0);
    QVERIFY(!times.gpuTimed());
    const auto frame = [](double gpu, double wall) {
        render::FrameStats stats;
        stats.gpuMilliseconds = gpu;
        stats.wallMilliseconds = wall;
        return stats;
    };
    times.add(frame(3.0, 10.0));
    times.add(frame(1.0, 30.0));
    times.add(frame(2.0, 20.0));
    QVERIFY(times.gpuTimed());
    QCOMPARE(times.medianMilliseconds(), 2.0);
    QCOMPARE(times.source(), std::string_view("GPU"));
    times.add(frame(-1.0, 40.0)); // an implausible GPU time: the wall median speaks
    QVERIFY(!times.gpuTimed());
    QCOMPARE(times.medianMilliseconds(), 25.0); // mean of 20 and 30
    QCOMPARE(times.medianGpuMilliseconds(), 2.0);
    QCOMPARE(times.source(), std::string_view("wall"));
    QCOMPARE(times.frames(), 4);
}

// A GPU memory budget below the chosen k⁺-buffer's storage: the view renders with the
// S-buffer instead (and the frame agrees with the reference), the status bar says why;
// a budget no GPU method fits shows the CPU reference as a still image (the same image
// as the reference renders for that view); no budget: the chosen method again.
void TestMethodPanel::memoryBudgetFallsBackToLeanerMethods()
{
    auto window = showWindow(QStringLiteral("budget"));
    auto* budget = child<QSpinBox>(window.get(), "memoryBudgetSpinBox");
    QVERIFY(budget);
    ViewportWidget* viewport = window->viewport();
    QVERIFY(waitForFrame(
        *window, [](const ViewportFrame& f) { return f.stats.method == render::FragmentMethodKind::KPlusArray; }));
    const std::size_t kplusBytes = *viewport->memoryEstimate().bytes;
    const int megabytes = int(kplusBytes / (2 * 1024 * 1024)); // half of what it needs
    QVERIFY(megabytes >= 2);
    budget->setValue(megabytes);
    QVERIFY(waitForFrame(*window,
                         [](const ViewportFrame& f) { return f.stats.method == render::FragmentMethodKind::SBuffer; }));
    QCOMPARE(viewport->method(), render::FragmentMethodKind::KPlusArray); // the choice is kept
    QCOMPARE(viewport->effectiveMethod(), render::FragmentMethodKind::SBuffer);
    // The status bar hears of it through a queued signal.
    QVERIFY2(QTest::qWaitFor(
                 [&] {
                     const QString message = window->statusBar()->currentMessage();
                     return message.contains(QStringLiteral("budget")) && message.contains(QStringLiteral("S-buffer"));
                 },
                 kWaitMs),
             qPrintable(window->statusBar()->currentMessage()));
    const auto failure = disagreement(*window, QStringLiteral("budget-fallback"));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");

    // 1 MB at 1024×768 holds neither the S-buffer's fragments (about 2.7 MB) nor peeling's images.
    viewport->setFixedSize(1024, 768);
    budget->setValue(1);
    QVERIFY(QTest::qWaitFor([&] { return viewport->showsCpuStill() && !viewport->cpuStillImage().isNull(); }, kWaitMs));
    QVERIFY2(
        QTest::qWaitFor([&] { return window->statusBar()->currentMessage().contains(QStringLiteral("CPU reference")); },
                        kWaitMs),
        qPrintable(window->statusBar()->currentMessage()));
    const QImage still = viewport->cpuStillImage().convertToFormat(QImage::Format_RGBA8888);
    const QSize size = viewport->framePixelSize();
    const ReferenceRenderer reference(window->scene()->scene);
    const ReferenceResult expected = reference.render(viewport->camera(), size.width(), size.height(),
                                                      window->renderWorkspace()->panel()->renderChoices().trim);
    QCOMPARE(still.size(), size);
    QVERIFY(still == render::toQImage(expected.color));
    QVERIFY(expected.stats.coveredPixels > std::uint64_t(size.width() * size.height() / 10));

    budget->setValue(0);
    QVERIFY(waitForFrame(
        *window, [](const ViewportFrame& f) { return f.stats.method == render::FragmentMethodKind::KPlusArray; }));
    QVERIFY(!viewport->showsCpuStill());
}

namespace {

/// One wheel notch down over the middle of `widget`, delivered as the window system would
/// (through QApplication::notify, where focus and event filters act).
void wheelDown(QWidget* widget)
{
    const QPointF local(widget->width() / 2.0, widget->height() / 2.0);
    QWheelEvent event(local, widget->mapToGlobal(local), QPoint(), QPoint(0, -120), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(widget, &event);
}

} // namespace

// Scrolling the Render panel with the wheel changed whatever spin box or combo box passed
// under the cursor (k from 16 to 13) and re-rendered. The wheel now scrolls the panel and
// leaves unfocused controls alone; a control the user focused still takes the wheel.
void TestMethodPanel::wheelScrollsThePanelNotItsControls()
{
    auto window = showWindow(QStringLiteral("wheel"));
    QVERIFY(waitForFrame(*window, [](const ViewportFrame&) { return true; }));
    auto* k = child<QSpinBox>(window.get(), "kSpinBox");
    auto* combo = child<QComboBox>(window.get(), "methodComboBox");
    QVERIFY(k && combo && k->isEnabled());
    auto* panel = qobject_cast<QScrollArea*>(window->renderWorkspace()->dock()->widget());
    QVERIFY(panel);
    if (QWidget* focused = QApplication::focusWidget())
        focused->clearFocus(); // as after a click in the viewport: no panel control has the focus

    const int kBefore = k->value();
    const int methodBefore = combo->currentIndex();
    panel->verticalScrollBar()->setValue(0);
    wheelDown(k);
    wheelDown(combo);
    QCOMPARE(k->value(), kBefore);
    QCOMPARE(combo->currentIndex(), methodBefore);
    QVERIFY(!k->hasFocus() && !combo->hasFocus());
    if (panel->verticalScrollBar()->maximum() > 0) // the panel scrolled instead
        QVERIFY(panel->verticalScrollBar()->value() > 0);

    window->activateWindow(); // focus needs an active window (Xvfb has no window manager to give it)
    QVERIFY(QTest::qWaitForWindowActive(window.get()));
    k->setFocus();
    QVERIFY(QTest::qWaitFor([&] { return k->hasFocus(); }, kWaitMs));
    wheelDown(k);
    QCOMPARE(k->value(), kBefore - 1);
}

QTEST_MAIN(TestMethodPanel)
#include "tst_method_panel.moc"
