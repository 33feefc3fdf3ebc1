// The Surface panel's persisted choices (surface_settings_store.h) and the control-point
// tool's picking and selection rules (control_point_pick.h), without OpenGL.
#include "control_point_pick.h"
#include "surface_settings_store.h"

#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>

using namespace trimlab;
using namespace trimlab::ui;

class TestSurfaceChoices : public QObject {
    Q_OBJECT
private slots:
    void roundTrip();
    void unusableValuesFallBack();
    void nearestPointWithinRadius();
    void clickRules();
};

void TestSurfaceChoices::roundTrip()
{
    QTemporaryDir dir;
    QSettings settings(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
    SurfaceChoices choices;
    choices.segmentsU = 7;
    choices.segmentsV = 9;
    choices.patchDegree = 2;
    choices.scheme = SubdivisionScheme::Loop;
    choices.level = 5;
    choices.mode = SubdivisionMode::Uniform;
    choices.showNet = false;
    choices.normalStepFraction = 0.25;
    saveSurfaceChoices(settings, choices);
    QVERIFY(loadSurfaceChoices(settings) == choices);
}

void TestSurfaceChoices::unusableValuesFallBack()
{
    QTemporaryDir dir;
    QSettings settings(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
    settings.setValue(QStringLiteral("surface/segmentsU"), 100000);
    settings.setValue(QStringLiteral("surface/segmentsV"), QStringLiteral("many"));
    settings.setValue(QStringLiteral("surface/patchDegree"), 0);
    settings.setValue(QStringLiteral("surface/scheme"), QStringLiteral("doo-sabin"));
    settings.setValue(QStringLiteral("surface/level"), 6);
    settings.setValue(QStringLiteral("surface/mode"), QStringLiteral("adaptive"));
    settings.setValue(QStringLiteral("surface/normalStepFraction"), QStringLiteral("nan"));
    const SurfaceChoices loaded = loadSurfaceChoices(settings);
    QVERIFY(loaded == SurfaceChoices{});
}

void TestSurfaceChoices::nearestPointWithinRadius()
{
    const std::vector<std::optional<QPointF>> points{QPointF(10, 10), std::nullopt, QPointF(14, 10),
                                                     QPointF(100, 100), QPointF(14, 10)};
    QCOMPARE(nearestPoint(QPointF(11, 10), points, 8.0), std::optional<std::uint32_t>(0));
    QCOMPARE(nearestPoint(QPointF(13, 10), points, 8.0), std::optional<std::uint32_t>(2)); // tie with 4: lower
    QCOMPARE(nearestPoint(QPointF(50, 50), points, 8.0), std::optional<std::uint32_t>());
    QCOMPARE(nearestPoint(QPointF(100, 108), points, 8.0), std::optional<std::uint32_t>(3)); // on the radius
    QCOMPARE(nearestPoint(QPointF(100, 108.01), points, 8.0), std::optional<std::uint32_t>());
}

void TestSurfaceChoices::clickRules()
{
    using Selection = std::vector<std::uint32_t>;
    QCOMPARE(clickedSelection({1, 5}, 3u, false), Selection{3});
    QCOMPARE(clickedSelection({1, 5}, std::nullopt, false), Selection{});
    QCOMPARE(clickedSelection({1, 5}, 3u, true), (Selection{1, 3, 5}));
    QCOMPARE(clickedSelection({1, 3, 5}, 3u, true), (Selection{1, 5}));
    QCOMPARE(clickedSelection({1, 5}, std::nullopt, true), (Selection{1, 5}));
}

QTEST_GUILESS_MAIN(TestSurfaceChoices)
#include "tst_surface_choices.moc"
