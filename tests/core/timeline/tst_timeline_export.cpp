// Exporting timeline frames as a numbered OBJ sequence that TrimLab's loaders read back.
#include "test_paths.h"
#include "tst_timeline_fixtures.h"

#include "core/mesh/mesh_io.h"
#include "core/timeline/frame_export.h"

#include <QtTest>

using namespace trimlab;
using namespace trimlab::timeline;

class TestTimelineExport : public QObject {
    Q_OBJECT
private slots:
    void objSequenceReloadsEveryFrame();
    void objSequenceRefusesBadNames();
};

void TestTimelineExport::objSequenceReloadsEveryFrame()
{
    const Timeline t = test::exportTimeline();
    const std::filesystem::path dir = test::outputDir() / "obj-sequence";
    std::filesystem::remove_all(dir);
    const std::vector<std::filesystem::path> files = exportObjSequence(t, dir / "nested", "sculpt");
    QCOMPARE(int(files.size()), t.frameCount());
    QCOMPARE(files.front().filename().string(), std::string("sculpt_0000.obj"));
    QCOMPARE(files.back().filename().string(), std::string("sculpt_0005.obj"));
    for (int f = 0; f < t.frameCount(); ++f) {
        const TriangleMesh mesh = loadMesh(files[std::size_t(f)]);
        QCOMPARE(mesh.triangles, t.base().triangles);
        const std::string difference = test::closeTo(mesh.positions, t.positionsAt(f), 1e-6);
        QVERIFY2(difference.empty(), qPrintable(QString("frame %1: %2").arg(f).arg(difference.c_str())));
    }
}

void TestTimelineExport::objSequenceRefusesBadNames()
{
    const Timeline t = test::exportTimeline();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)exportObjSequence(t, test::outputDir(), ""));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)exportObjSequence(t, test::outputDir(), "a/b"));
}

QTEST_GUILESS_MAIN(TestTimelineExport)
#include "tst_timeline_export.moc"
