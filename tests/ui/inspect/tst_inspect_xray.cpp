// X-ray as a user sets it in the Render panel: the choices through the settings store
// (round trip, broken values falling back field by field) and through the panel's
// widgets, then the real main window: X-ray switched on with the keyboard and typed
// values, the frame's colors different from the opaque frame where the trim removed
// fragments, its ids unchanged and agreeing with the CPU reference, and its colors
// within 2/255 of the reference's on >= 99.9 % of the pixels whose ray hits anything
// (the tolerance of tests/render/tst_transparency_methods.cpp, justified there).
#include "color_check.h"
#include "inspect_window.h"

#include "ui/render_panel/inspect_group.h"
#include "ui/render_panel/render_panel.h"
#include "ui/render_panel/render_settings_store.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLocale>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>

using namespace trimlab;
using namespace trimlab::ui;
using namespace trimlab::test;

namespace {

const QString kSphere = QStringLiteral("demo:pushed-sphere");

void typeValue(QDoubleSpinBox* spin, double value)
{
    revealed(spin)->setFocus();
    QTest::keyClick(spin, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(spin, QLocale().toString(value));
    QTest::keyClick(spin, Qt::Key_Return);
}

// Colors of the last frame against the reference; nullopt when they agree.
std::optional<QString> colorDisagreement(MainWindow& window, const QString& name)
{
    const QImage actual = window.viewport()->readColorImage(); // first: lastFrame() is then its frame
    const ReferenceResult expected = referenceOfLastFrame(window);
    const ColorComparison colors =
        compareColors(actual, window.viewport()->readTrimImage(), expected.color, expected.diagnostics, 2);
    qInfo("%s: %s", qPrintable(name), qPrintable(colors.summary()));
    const std::uint64_t pixels = std::uint64_t(actual.width()) * std::uint64_t(actual.height());
    return colorViolation(colors, actual, expected.color, name, 0.999, pixels / 20);
}

int differingPixels(const QImage& a, const QImage& b)
{
    const QImage x = a.convertToFormat(QImage::Format_RGBA8888);
    const QImage y = b.convertToFormat(QImage::Format_RGBA8888);
    int count = 0;
    for (int row = 0; row < x.height(); ++row)
        for (int column = 0; column < x.width(); ++column)
            count += x.pixel(column, row) != y.pixel(column, row) ? 1 : 0;
    return count;
}

} // namespace

class TestInspectXray : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void choicesRoundTripAndFallBack();
    void panelShowsWhatItIsGiven();
    void xrayThroughTheWidgetsMatchesTheReference();

private:
    QTemporaryDir m_dir;
};

void TestInspectXray::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QVERIFY(m_dir.isValid());
}

void TestInspectXray::choicesRoundTripAndFallBack()
{
    RenderChoices saved = firstStartRenderChoices();
    saved.trim.transparency = {true, TrimDisplay::Opaque, 0.625, 0.125, 2.5, 3.0};
    const QString ini = m_dir.filePath(QStringLiteral("roundtrip.ini"));
    {
        QSettings settings(ini, QSettings::IniFormat);
        saveRenderChoices(settings, saved);
    }
    {
        QSettings settings(ini, QSettings::IniFormat);
        QVERIFY(loadRenderChoices(settings).trim.transparency == saved.trim.transparency);
        settings.setValue(QStringLiteral("render/xrayMode"), QStringLiteral("off"));
        QVERIFY(!loadRenderChoices(settings).trim.transparency.enabled);
        // Broken values fall back one by one to the first start's.
        settings.setValue(QStringLiteral("render/xrayMode"), QStringLiteral("sideways"));
        settings.setValue(QStringLiteral("render/xrayLayerAlpha"), 1.5);
        settings.setValue(QStringLiteral("render/xrayGhostAlpha"), QStringLiteral("nan"));
        settings.setValue(QStringLiteral("render/xrayDensity"), -1.0);
        const TransparencySettings loaded = loadRenderChoices(settings).trim.transparency;
        const TransparencySettings first = firstStartRenderChoices().trim.transparency;
        QCOMPARE(loaded.enabled, first.enabled);
        QCOMPARE(loaded.layerAlpha, first.layerAlpha);
        QCOMPARE(loaded.ghostAlpha, first.ghostAlpha);
        QCOMPARE(loaded.density, first.density);
        QCOMPARE(loaded.fresnelExponent, 3.0); // still good
    }
    QSettings empty(m_dir.filePath(QStringLiteral("empty.ini")), QSettings::IniFormat);
    QVERIFY(!loadRenderChoices(empty).trim.transparency.enabled); // off at first start
}

void TestInspectXray::panelShowsWhatItIsGiven()
{
    RenderPanel panel;
    RenderChoices choices = firstStartRenderChoices();
    choices.trim.transparency = {true, TrimDisplay::Translucent, 0.35, 0.2, 1.25, 2.0};
    panel.setRenderChoices(choices);
    QVERIFY(panel.renderChoices().trim.transparency == choices.trim.transparency);
    auto* mode = panel.findChild<QComboBox*>(QStringLiteral("xrayModeComboBox"));
    QVERIFY(mode);
    QCOMPARE(mode->currentText(), QStringLiteral("Translucent"));
    choices.trim.transparency.display = TrimDisplay::Opaque;
    panel.setRenderChoices(choices);
    QVERIFY(!panel.findChild<QDoubleSpinBox*>(QStringLiteral("xrayLayerAlphaSpin"))->isEnabled());
    QVERIFY(panel.findChild<QDoubleSpinBox*>(QStringLiteral("xrayGhostAlphaSpin"))->isEnabled());
    choices.trim.transparency.enabled = false;
    panel.setRenderChoices(choices);
    QCOMPARE(mode->currentText(), QStringLiteral("Off"));
    QVERIFY(!panel.renderChoices().trim.transparency.enabled);
}

void TestInspectXray::xrayThroughTheWidgetsMatchesTheReference()
{
    std::unique_ptr<render::OffscreenGlContext> probe;
    TRIMLAB_INIT_GL_CONTEXT(probe);
    probe.reset();
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("xray.ini")), kSphere);
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) { return !f.settings.transparency.enabled; }));
    const QImage opaque = window->viewport()->readColorImage();
    const TrimImage opaqueIds = window->viewport()->readTrimImage();

    // Off -> Opaque trim + ghosts, with the keyboard; ghost opacity typed.
    auto* mode = child<QComboBox>(window.get(), "xrayModeComboBox");
    QTest::keyClick(revealed(mode), Qt::Key_Down);
    typeValue(child<QDoubleSpinBox>(window.get(), "xrayGhostAlphaSpin"), 0.5);
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) {
        return f.settings.transparency.enabled && f.settings.transparency.display == TrimDisplay::Opaque &&
               f.settings.transparency.ghostAlpha == 0.5;
    }));
    const QImage ghosts = window->viewport()->readColorImage();
    QCOMPARE(changedPixels(window->viewport()->readTrimImage(), opaqueIds), 0); // the ids stay
    const int changed = differingPixels(ghosts, opaque);
    QVERIFY2(changed > 100, qPrintable(QString::number(changed)));
    if (const auto failure = inspectDisagreement(*window, QStringLiteral("xray-ghosts")))
        QFAIL(qPrintable(*failure));
    if (const auto failure = colorDisagreement(*window, QStringLiteral("xray-ghosts-colors")))
        QFAIL(qPrintable(*failure));

    // -> Translucent with density and Fresnel.
    QTest::keyClick(revealed(mode), Qt::Key_Down);
    typeValue(child<QDoubleSpinBox>(window.get(), "xrayDensitySpin"), 0.75);
    typeValue(child<QDoubleSpinBox>(window.get(), "xrayFresnelSpin"), 2.0);
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) {
        return f.settings.transparency.display == TrimDisplay::Translucent && f.settings.transparency.density == 0.75 &&
               f.settings.transparency.fresnelExponent == 2.0;
    }));
    QVERIFY(differingPixels(window->viewport()->readColorImage(), ghosts) > 100);
    if (const auto failure = colorDisagreement(*window, QStringLiteral("xray-translucent-colors")))
        QFAIL(qPrintable(*failure));
}

QTEST_MAIN(TestInspectXray)
#include "tst_inspect_xray.moc"
