// Exporting a timeline as a glTF 2.0 morph-target animation: the Khronos glTF Validator
// reports no errors, and TrimLab's own glTF animation loader reproduces every frame.
#include "test_paths.h"
#include "tst_timeline_fixtures.h"

#include "core/animation/gltf_animation.h"
#include "core/timeline/frame_export.h"

#include <QProcess>
#include "gltf_validation.h"

#include <QtTest>

using namespace trimlab;
using namespace trimlab::timeline;

namespace {

void requireFramesReproduced(const std::filesystem::path& file, const Timeline& t, double fps)
{
    const MeshAnimation animation = loadGltfAnimation(file);
    QCOMPARE(int(animation.poseCount()), t.frameCount());
    QCOMPARE(animation.triangles, t.base().triangles);
    for (int f = 0; f < t.frameCount(); ++f) {
        QVERIFY(std::abs(animation.poseTimes[std::size_t(f)] - f / fps) < 1e-6);
        const std::string difference = test::closeTo(animation.poses[std::size_t(f)], t.positionsAt(f), 1e-6);
        QVERIFY2(difference.empty(), qPrintable(QString("frame %1: %2").arg(f).arg(difference.c_str())));
    }
}

} // namespace

class TestTimelineGltf : public QObject {
    Q_OBJECT
private slots:
    void glbPassesTheValidatorAndReloads();
    void embeddedGltfPassesTheValidatorAndReloads();
    void timelineWithoutStrokesIsAStaticMesh();
    void refusesBadFps();
};

void TestTimelineGltf::glbPassesTheValidatorAndReloads()
{
    const Timeline t = test::exportTimeline();
    const std::filesystem::path file = test::outputDir() / "timeline.glb";
    exportMorphGltf(t, file, 24.0);
    test::requireValidGltf(file);
    requireFramesReproduced(file, t, 24.0);
}

void TestTimelineGltf::embeddedGltfPassesTheValidatorAndReloads()
{
    const Timeline t = test::exportTimeline();
    const std::filesystem::path file = test::outputDir() / "timeline.gltf";
    exportMorphGltf(t, file, 10.0);
    QVERIFY(morphGltf(t, 10.0, false).starts_with("{"));
    test::requireValidGltf(file);
    requireFramesReproduced(file, t, 10.0);
}

void TestTimelineGltf::timelineWithoutStrokesIsAStaticMesh()
{
    const Timeline t(test::gridMesh(4));
    const std::filesystem::path file = test::outputDir() / "static.glb";
    exportMorphGltf(t, file);
    test::requireValidGltf(file);
}

void TestTimelineGltf::refusesBadFps()
{
    const Timeline t = test::exportTimeline();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)morphGltf(t, 0.0, true));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)morphGltf(t, std::nan(""), true));
}

QTEST_GUILESS_MAIN(TestTimelineGltf)
#include "tst_timeline_gltf.moc"
