// `trimlab render` of a .trimlab project renders it as it was saved: the project's static
// rule and its classification (static or dynamic) apply unless --rule or
// --classification choose otherwise.
#include "run_trimlab.h"

#include "core/scene/shape_generators.h"
#include "core/timeline/project_file.h"
#include "core/timeline/stroke_replay.h"
#include "core/timeline/stroke_script.h"
#include "core/util/task_control.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace trimlab;
using trimlab::test::Run;
using trimlab::test::runTrimlab;

namespace {

const char* const kScript = TRIMLAB_TEST_DATA_DIR "/scripts/fig8_7_extended_tip.json";

/// demo:sphere's mesh with the script's strokes: a design whose last frame has frames
/// before it, so the dynamic and the static classification differ in what they print.
timeline::Timeline designedSphere()
{
    const TriangleMesh sphere = makeIcosphere(glm::dvec3(0.0), 1.0, 4); // demo:sphere's
    return timeline::replayStrokeScript(sphere, timeline::loadStrokeScript(kScript), TaskControl{}, "script");
}

QString saveProject(const QString& path, timeline::Classification classification, StaticRule rule)
{
    timeline::ProjectExtras extras;
    extras.staticRule = rule;
    timeline::StoredViewSettings settings;
    settings.classification = classification;
    extras.viewSettings = settings;
    timeline::saveProject(designedSphere(), path.toStdString(), extras);
    return path;
}

Run render(const QString& project, const QStringList& more, const QString& output)
{
    return runTrimlab(QStringList{QStringLiteral("render"), project, QStringLiteral("--backend"),
                                  QStringLiteral("reference"), QStringLiteral("--size"), QStringLiteral("48x32"),
                                  QStringLiteral("-o"), output} +
                      more);
}

} // namespace

class TestRenderProject : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }
    void aStaticProjectRendersStatically();
    void aDynamicProjectRendersDynamically();
    void theCommandLineChoosesOtherwise();

private:
    QTemporaryDir m_dir;
};

void TestRenderProject::aStaticProjectRendersStatically()
{
    const QString project =
        saveProject(m_dir.filePath("static.trimlab"), timeline::Classification::Static, StaticRule::Parity);
    const Run run = render(project, {}, m_dir.filePath("static.png"));
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.out.contains(QStringLiteral("parity (static)")), qPrintable(run.out));
}

void TestRenderProject::aDynamicProjectRendersDynamically()
{
    const QString project =
        saveProject(m_dir.filePath("dynamic.trimlab"), timeline::Classification::Dynamic, StaticRule::Parity);
    const Run run = render(project, {}, m_dir.filePath("dynamic.png"));
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.out.contains(QStringLiteral("dynamic: parity on the base mesh")), qPrintable(run.out));
}

void TestRenderProject::theCommandLineChoosesOtherwise()
{
    const QString project =
        saveProject(m_dir.filePath("chosen.trimlab"), timeline::Classification::Static, StaticRule::Parity);
    const Run run = render(project,
                           {QStringLiteral("--classification"), QStringLiteral("dynamic"), QStringLiteral("--rule"),
                            QStringLiteral("nonzero")},
                           m_dir.filePath("chosen.png"));
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.out.contains(QStringLiteral("dynamic: nonzero on the base mesh")), qPrintable(run.out));
}

QTEST_GUILESS_MAIN(TestRenderProject)
#include "tst_render_project.moc"
