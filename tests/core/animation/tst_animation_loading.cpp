// Loading mesh animations from files: natural order, folders and patterns, the pose
// consistency checks with their messages (tests/data/animations/, hand-written OBJ),
// re-triangulated polygons, welding across poses, progress and cancellation.
#include "core/animation/animation_load_parameters.h"
#include "core/animation/animation_loader.h"
#include "core/animation/natural_order.h"
#include "core/animation/pose_welding.h"
#include "core/animation/sequence_files.h"
#include "core/animation/sequence_loader.h"
#include "core/mesh/mesh_load_error.h"

#include "test_paths.h"

#include <QtTest>

#include <algorithm>

using namespace trimlab;
using trimlab::test::sharedDataPath;
using trimlab::test::testDataPath;

namespace {

std::string animations(const std::string& relative)
{
    return testDataPath("animations/" + relative).string();
}

// The message of the MeshLoadError `load` throws, or "" when it does not throw one.
template <class Load>
QString loadError(const Load& load)
{
    try {
        load();
    } catch (const MeshLoadError& e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

std::vector<std::string> fileNames(const std::vector<std::filesystem::path>& files)
{
    std::vector<std::string> names;
    for (const auto& f : files)
        names.push_back(f.filename().string());
    return names;
}

} // namespace

class TestAnimationLoading : public QObject {
    Q_OBJECT
private slots:
    void naturalOrder();
    void folderLoadsInNaturalOrder();
    void patternsSelectFiles();
    void patternErrors();
    void mismatchedFaceNamesFileAndFace();
    void mismatchedVertexCountNamesFile();
    void brokenPoseNamesFile();
    void retriangulatedQuadIsAccepted();
    void restPoseIsChosen();
    void loadRowsDescribeTheLoader();
    void weldingKeepsSeamsThatOpen();
    void progressAndCancel();
    void walkingCatLoads();
};

void TestAnimationLoading::naturalOrder()
{
    QVERIFY(naturalLess("mesh_2.obj", "mesh_10.obj"));
    QVERIFY(!naturalLess("mesh_10.obj", "mesh_2.obj"));
    QVERIFY(naturalLess("mesh_0009.obj", "mesh_0010.obj"));
    QVERIFY(naturalLess("Frame_3", "frame_4"));                                    // letters ignore case
    QVERIFY(naturalLess("f7", "f007"));                                            // equal numbers: fewer zeros first
    QVERIFY(naturalLess("a99999999999999999999999", "a100000000000000000000000")); // no overflow
    std::vector<std::string> names = {"mesh_10", "mesh_2", "mesh_1", "mesh_02b", "mesh_100"};
    std::sort(names.begin(), names.end(), [](const std::string& a, const std::string& b) { return naturalLess(a, b); });
    QCOMPARE(names, (std::vector<std::string>{"mesh_1", "mesh_2", "mesh_02b", "mesh_10", "mesh_100"}));
}

// bar/ holds bar_1 (flat), bar_2 (folded down) and bar_10 (folded up): a plain sort would
// put bar_10 second.
void TestAnimationLoading::folderLoadsInNaturalOrder()
{
    const MeshAnimation a = loadAnimation(animations("bar"));
    QCOMPARE(a.poseCount(), std::size_t(3));
    QCOMPARE(a.vertexCount(), std::size_t(10));
    QCOMPARE(a.triangleCount(), std::size_t(8));
    QCOMPARE(a.poseNames, (std::vector<std::string>{"bar_1.obj", "bar_2.obj", "bar_10.obj"}));
    QCOMPARE(a.poses[0][3], glm::vec3(3, 0, 0));
    QCOMPARE(a.poses[1][3], glm::vec3(2, 0, -1));
    QCOMPARE(a.poses[2][3], glm::vec3(2, 0, 1));
    QCOMPARE(a.restPose, std::size_t(0));
    QVERIFY(a.poseTimes.empty());
}

void TestAnimationLoading::patternsSelectFiles()
{
    QCOMPARE(fileNames(sequenceFiles(animations("bar/bar_%d.obj"))),
             (std::vector<std::string>{"bar_1.obj", "bar_2.obj", "bar_10.obj"}));
    QCOMPARE(fileNames(sequenceFiles(animations("bar/bar_*.obj"))),
             (std::vector<std::string>{"bar_1.obj", "bar_2.obj", "bar_10.obj"}));
    QCOMPARE(fileNames(sequenceFiles(animations("bar/bar_?.obj"))),
             (std::vector<std::string>{"bar_1.obj", "bar_2.obj"}));
    QCOMPARE(fileNames(sequenceFiles(animations("bar/bar_%02d.obj"))), (std::vector<std::string>{"bar_10.obj"}));
    QCOMPARE(sequenceFiles(animations("mismatched_faces/mesh_%04d.obj")).size(), std::size_t(3));
    QVERIFY(isGltfSource("x/walk.GLB"));
    QVERIFY(isGltfSource("walk.gltf.gz"));
    QVERIFY(!isGltfSource("dir/mesh_%04d.obj.gz"));
}

void TestAnimationLoading::patternErrors()
{
    QVERIFY(loadError([] { (void)sequenceFiles(animations("bar/none_*.obj")); }).contains("no file in"));
    QVERIFY(
        loadError([] { (void)sequenceFiles(animations("bar/bar_%s.obj")); }).contains("malformed numbered pattern"));
    QVERIFY(loadError([] { (void)sequenceFiles(animations("nowhere")); }).contains("no such folder or file"));
    QVERIFY(loadError([] { (void)sequenceFiles(animations("bar/bar_1.obj")); }).contains("not an animation"));
    QVERIFY(loadError([] { (void)sequenceFiles(animations("b*r/bar_1.obj")); }).contains("only in the file name"));
}

// mesh_0002.obj changes the third corner of face 5 (0-based) from vertex 7 to 9.
void TestAnimationLoading::mismatchedFaceNamesFileAndFace()
{
    const QString message = loadError([] { (void)loadAnimation(animations("mismatched_faces")); });
    QVERIFY2(message.contains("mesh_0002.obj: face 5 is (2, 8, 9) but the first pose has (2, 8, 7)"),
             qPrintable(message));
}

void TestAnimationLoading::mismatchedVertexCountNamesFile()
{
    const QString message = loadError([] { (void)loadAnimation(animations("mismatched_vertices/mesh_%04d.obj")); });
    QVERIFY2(message.contains("mesh_0001.obj: has 11 vertices but the first pose has 10"), qPrintable(message));
}

void TestAnimationLoading::brokenPoseNamesFile()
{
    const QString message = loadError([] { (void)loadAnimation(animations("broken_pose")); });
    QVERIFY2(message.contains("mesh_0001.obj:9:") && message.contains("nan"), qPrintable(message));
}

// pose_1.obj splits its second quad along the other diagonal: the same surface, accepted,
// and every pose uses pose_0's triangles.
void TestAnimationLoading::retriangulatedQuadIsAccepted()
{
    const MeshAnimation a = loadAnimation(animations("retriangulated"));
    QCOMPARE(a.poseCount(), std::size_t(2));
    QCOMPARE(a.triangles[2], glm::uvec3(1, 2, 7));
    QCOMPARE(a.triangles[3], glm::uvec3(1, 7, 6));
}

void TestAnimationLoading::restPoseIsChosen()
{
    AnimationLoadOptions options;
    options.restPose = 2;
    QCOMPARE(loadAnimation(animations("bar"), options).restPose, std::size_t(2));
    options.restPose = 3;
    const QString message = loadError([&] { (void)loadAnimation(animations("bar"), options); });
    QVERIFY2(message.contains("the rest pose 3 does not exist; the animation has 3 poses (0 to 2)"),
             qPrintable(message));
}

// The verbs' rows for loading start where the loader does and accept what it accepts: a
// rest pose from 0, and a sampling rate of 0 meaning the file's own keyframes.
void TestAnimationLoading::loadRowsDescribeTheLoader()
{
    using namespace animation_load_parameters;
    static_assert(isWellFormed(kRestPose) && isWellFormed(kGltfAnimation) && isWellFormed(kGltfFps));
    QCOMPARE(kRestPose.defaultValue, double(AnimationLoadOptions{}.restPose));
    QCOMPARE(kGltfAnimation.defaultValue, double(GltfAnimationOptions{}.animation));
    QCOMPARE(kGltfFps.defaultValue, GltfAnimationOptions{}.fps);
    QVERIFY(!acceptsValue(kRestPose, -1) && acceptsValue(kRestPose, 0));
    QVERIFY(acceptsValue(kGltfFps, 0) && !acceptsValue(kGltfFps, -0.5));
    QVERIFY(parameterHelpText(kGltfFps).find("0 = at its keyframes") != std::string::npos);
    // The row's value reaches the loader as it is read.
    AnimationLoadOptions options;
    options.restPose = std::size_t(*parseParameterValue(kRestPose, "1"));
    QCOMPARE(loadAnimation(animations("bar"), options).restPose, std::size_t(1));
}

// Vertices 0 and 1 coincide in both poses (a seam): welded. Vertices 2 and 3 coincide only
// in the first pose (a seam that opens): kept apart.
void TestAnimationLoading::weldingKeepsSeamsThatOpen()
{
    MeshAnimation a;
    a.triangles = {{0, 2, 4}, {1, 3, 4}};
    a.poses = {{{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 1, 0}},
               {{0, 0, 1}, {0, 0, 1}, {1, 0, 1}, {1, 0, 2}, {0, 1, 1}}};
    const MeshAnimation welded = weldAcrossPoses(a);
    QCOMPARE(welded.vertexCount(), std::size_t(4));
    QCOMPARE(welded.triangles[0], glm::uvec3(0, 1, 3));
    QCOMPARE(welded.triangles[1], glm::uvec3(0, 2, 3));
    QCOMPARE(welded.poses[1][2], glm::vec3(1, 0, 2));
}

void TestAnimationLoading::progressAndCancel()
{
    std::vector<std::size_t> done;
    std::vector<std::size_t> totals;
    TaskControl control;
    control.progress = [&](const TaskProgress& p) {
        QCOMPARE(p.stage, std::string_view("load"));
        done.push_back(p.done);
        totals.push_back(p.total);
    };
    (void)loadMeshSequence(sequenceFiles(animations("bar")), control, 1);
    QVERIFY(!done.empty());
    QVERIFY(std::is_sorted(done.begin(), done.end()));
    // Every file of the sequence counts: the dialog read "(2 of 2)" for three poses.
    QCOMPARE(done.back(), std::size_t(3));
    QVERIFY(std::all_of(totals.begin(), totals.end(), [](std::size_t t) { return t == 3; }));
    std::stop_source stop;
    stop.request_stop();
    TaskControl cancelled;
    cancelled.stop = stop.get_token();
    QVERIFY_THROWS_EXCEPTION(OperationCancelled, (void)loadAnimation(animations("bar"), {}, cancelled));
}

// The walking cat's polygons are triangulated per pose; some quads split differently in
// some frames, which must load.
void TestAnimationLoading::walkingCatLoads()
{
    const std::filesystem::path folder = sharedDataPath("anim/walking-cat");
    if (!std::filesystem::exists(folder))
        QSKIP("../shared/data/anim/walking-cat is missing");
    const MeshAnimation a = loadAnimation(folder.string());
    QCOMPARE(a.poseCount(), std::size_t(35));
    QCOMPARE(a.vertexCount(), std::size_t(1297));
    QCOMPARE(a.poseNames.front(), std::string("mesh.01.obj.gz"));
    QCOMPARE(a.poseNames.back(), std::string("mesh.35.obj.gz"));
}

QTEST_GUILESS_MAIN(TestAnimationLoading)
#include "tst_animation_loading.moc"
