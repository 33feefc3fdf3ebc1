// The Surface panel's persisted choices (surface_settings_store.h), without OpenGL.
#include "ui/surface/surface_settings_store.h"

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

QTEST_GUILESS_MAIN(TestSurfaceChoices)
#include "tst_surface_choices.moc"
