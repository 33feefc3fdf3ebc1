// File ▸ Export Trimmed Solid in the window: the CSG of the csg-trio demo as the Scene
// panel holds it, exported off the UI thread, is the closed mesh the core computes for
// the frame's own scene and settings (read back by TrimLab's loader); a view without a
// solid (trimming off, a design under dynamic rules) is refused with its reason first and
// writes nothing. Cut by a clipping plane, the solid as shown is exported cut and capped.
// An animation shown exports every pose, each trimmed on its own, as one glTF sequence.
#include "inspect_window.h"
#include "message_box_closer.h"
#include "test_paths.h"

#include "ui/inspect/inspect_scene.h"
#include "ui/inspect/inspect_workspace.h"
#include "ui/inspect/solid_export.h"
#include "ui/design/design_workspace.h"
#include "ui/animation/animation_workspace.h"
#include "ui/animation/timeline_panel.h"
#include "ui/common/loaded_animation.h"
#include "ui/viewport/viewport_widget.h"
#include "render/shown_content.h"

#include "core/catalog/pose_scene.h"
#include "core/catalog/scene_source.h"
#include "core/io/file_bytes.h"
#include "core/mesh/gltf_document.h"
#include "core/mesh/mesh_validation.h"
#include "core/trim/csg_expression.h"

#include <QCheckBox>
#include <QComboBox>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>

using namespace trimlab;
using namespace trimlab::ui;
using namespace trimlab::test;

Q_DECLARE_METATYPE(trimlab::TrimmedSolidStats)

class TestInspectSolidExport : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void exportsTheCsgShown();
    void refusesWithoutASolid();
    void refusesDynamicRulesWithTheReasonFirst();
    void exportsTheCutAsShown();
    void exportsEveryPoseOfAnAnimation();

private:
    QTemporaryDir m_dir;
};

void TestInspectSolidExport::initTestCase()
{
    TRIMLAB_SKIP_WITHOUT_GL();
    QVERIFY(m_dir.isValid());
}

void TestInspectSolidExport::exportsTheCsgShown()
{
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("export.ini")), QStringLiteral("demo:csg-trio"));
    InspectScene* scene = window->inspectWorkspace()->scene();
    CsgSettings csg = scene->csg();
    csg.expression = parseCsgExpression("0 | 1 - 2", nullptr).value();
    csg.objectRules[0] = StaticRule::AlternatingBorder;
    scene->editCsg(csg, QStringLiteral("test CSG"));
    QVERIFY(waitForFrame(*window, [&](const ViewportFrame& f) { return f.settings.csg == csg; }));
    const ViewportFrame frame = *window->viewport()->lastFrame();

    const QString path = m_dir.filePath(QStringLiteral("trio.ply"));
    QSignalSpy exported(window->solidExport(), &SolidExport::exported);
    window->solidExport()->exportTo(path);
    QVERIFY(window->solidExport()->isExporting() || !exported.isEmpty());
    QVERIFY(exported.wait(60000));
    QCOMPARE(exported.front().at(0).toString(), path);

    const TrimmedSolid expected = trimmedSolid(*frame.scene, frame.settings);
    const LoadedScene written = loadScene(path.toStdString());
    QCOMPARE(written.scene.objects.front().mesh.triangles.size(), expected.mesh.triangles.size());
    const MeshValidationReport& report = written.reports.front();
    QVERIFY2(report.closed(), formatReport(report, "export").c_str());
    QVERIFY(std::abs(report.signedVolume - expected.stats.signedVolume) <= 1e-4 * expected.stats.signedVolume);
    QVERIFY(window->statusBar()->currentMessage().contains(QStringLiteral("Exported the trimmed solid")));
}

void TestInspectSolidExport::refusesWithoutASolid()
{
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("refuse.ini")), QStringLiteral("demo:csg-trio"));
    QTest::keyClick(revealed(child<QCheckBox>(window.get(), "trimCheckBox")), Qt::Key_Space);
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) { return !f.settings.trimEnabled; }));
    MessageBoxCloser closer;
    QSignalSpy failed(window->solidExport(), &SolidExport::failed);
    const QString path = m_dir.filePath(QStringLiteral("nothing.obj"));
    window->solidExport()->exportTo(path);
    QVERIFY(failed.count() == 1 || failed.wait(10000));
    QVERIFY2(failed.front().at(1).toString().contains(QStringLiteral("Trimming is off")),
             qPrintable(failed.front().at(1).toString()));
    QVERIFY(!QFile::exists(path));
    // The box's first line is the reason, not a generic "nothing to export".
    QVERIFY(QTest::qWaitFor([&] { return !closer.seen().isEmpty(); }, 5000));
    QVERIFY2(closer.seen().front().startsWith(QStringLiteral("Trimming is off")), qPrintable(closer.seen().front()));
}

// A design shown under its dynamic rules: File ▸ Export Trimmed Solid says first that
// dynamic rules cannot be exported exactly, then how to get a solid (the static rule).
void TestInspectSolidExport::refusesDynamicRulesWithTheReasonFirst()
{
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("dynamic.ini")), QStringLiteral("demo:sphere"));
    QVERIFY(window->designWorkspace()->session());
    QComboBox* classification = revealed(child<QComboBox>(window.get(), "classificationComboBox"));
    classification->setCurrentIndex(1);
    QVERIFY(QTest::qWaitFor([&] { return window->viewport()->content()->chain() != nullptr; }, 60000));
    MessageBoxCloser closer;
    window->solidExport()->showExportDialog();
    QVERIFY(QTest::qWaitFor([&] { return !closer.seen().isEmpty(); }, 5000));
    const QString message = closer.seen().front();
    QVERIFY2(message.startsWith(QStringLiteral("Dynamic rules cannot be exported exactly")), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("Static rule")), qPrintable(message));
}

// The trio cut by the Render panel's first clipping plane: exported as shown, the file is
// the closed solid cutTrimmedSolid gives for the frame, smaller than the whole solid.
void TestInspectSolidExport::exportsTheCutAsShown()
{
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("cut.ini")), QStringLiteral("demo:csg-trio"));
    QTest::mouseClick(revealed(child<QCheckBox>(window.get(), "clipPlaneEnabled0")), Qt::LeftButton);
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) { return f.settings.clipSet().anyEnabled(); }));
    const ViewportFrame frame = *window->viewport()->lastFrame();

    const QString path = m_dir.filePath(QStringLiteral("trio-cut.obj"));
    QSignalSpy exported(window->solidExport(), &SolidExport::exported);
    window->solidExport()->exportTo(path, SolidExport::Extent::AsShown);
    QVERIFY(exported.count() == 1 || exported.wait(60000));
    const TrimmedSolid expected = cutTrimmedSolid(*frame.scene, frame.settings);
    const double whole = trimmedSolid(*frame.scene, frame.settings).stats.signedVolume;
    const MeshValidationReport& report = loadScene(path.toStdString()).reports.front();
    QVERIFY2(report.trimmable(), formatReport(report, "cut").c_str());
    QVERIFY(std::abs(report.signedVolume - expected.stats.signedVolume) <= 1e-4 * expected.stats.signedVolume);
    QVERIFY2(report.signedVolume < 0.9 * whole,
             qPrintable(QStringLiteral("%1 of %2").arg(report.signedVolume).arg(whole)));
}

// The folding box (pose 2 folds through itself) opened as an animation: every pose is
// exported, each trimmed on its own, into one .glb whose node k holds the solid the core
// trims from pose k. A mesh shown has no poses: refused, nothing written.
void TestInspectSolidExport::exportsEveryPoseOfAnAnimation()
{
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("poses.ini")), QStringLiteral("demo:sphere"));
    const QString refusedPath = m_dir.filePath(QStringLiteral("sphere-poses.glb"));
    MessageBoxCloser closer;
    QSignalSpy failed(window->solidExport(), &SolidExport::failed);
    window->solidExport()->exportPosesTo(refusedPath);
    QCOMPARE(failed.count(), 1);
    QVERIFY2(failed.front().at(1).toString().contains(QStringLiteral("No animation is shown")),
             qPrintable(failed.front().at(1).toString()));
    QVERIFY(!QFile::exists(refusedPath));

    const QString source = QString::fromStdString(test::testDataPath("animations/folding_box").string());
    QSignalSpy loaded(window.get(), &MainWindow::animationLoaded);
    window->openAnimation(source);
    QVERIFY(QTest::qWaitFor([&] { return !loaded.isEmpty() && !window->isLoading(); }, kInspectWaitMs));
    QVERIFY(waitForFrame(*window, [&](const ViewportFrame& f) { return f.settings.trimEnabled; }));
    const std::shared_ptr<const MeshAnimation> animation = window->animation()->animation;
    QCOMPARE(animation->poseCount(), std::size_t(3));

    const QString path = m_dir.filePath(QStringLiteral("box-poses.glb"));
    QSignalSpy exported(window->solidExport(), &SolidExport::posesExported);
    window->solidExport()->exportPosesTo(path);
    QVERIFY(exported.count() == 1 || exported.wait(60000));
    QCOMPARE(exported.front().at(1).value<std::size_t>(), std::size_t(3));
    const TrimSettings settings = window->viewport()->lastFrame()->settings;
    const tinygltf::Model model =
        parseGltfDocument(io::readFileBytes(path.toStdString(), std::size_t(1) << 28), "box-poses.glb", {});
    QCOMPARE(model.meshes.size(), std::size_t(3));
    double total = 0.0;
    for (std::size_t pose = 0; pose < 3; ++pose) {
        const LoadedScene scene = animationPoseScene(*animation, pose, "pose", "pose");
        const TrimmedSolid expected = trimmedSolid(scene.scene, settings);
        total += expected.stats.signedVolume;
        const tinygltf::Primitive& primitive = model.meshes[pose].primitives.at(0);
        QCOMPARE(model.accessors[std::size_t(primitive.indices)].count, 3 * expected.mesh.triangles.size());
    }
    const double reported = exported.front().at(2).toDouble();
    QVERIFY2(std::abs(reported - total) <= 1e-9 * total,
             qPrintable(QStringLiteral("%1 vs %2").arg(reported).arg(total)));
    QVERIFY(window->statusBar()->currentMessage().contains(QStringLiteral("Exported 3 trimmed poses")));
}

QTEST_MAIN(TestInspectSolidExport)
#include "tst_inspect_solid_export.moc"
