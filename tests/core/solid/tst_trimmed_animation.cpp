// An animation trimmed pose by pose (core/solid/trimmed_animation.h) and the glTF that
// plays such a sequence (core/mesh/mesh_sequence_gltf.h): each pose's solid is the trim
// of that pose alone, delivered in order with the poses' progress; a pose that is not a
// closed surface is named; Cancel stops between poses. The sequence file passes the
// Khronos validator and shows exactly one pose's node at each pose's time.
#include "gltf_validation.h"
#include "gltf_values.h"
#include "test_paths.h"

#include "core/animation/animation_loader.h"
#include "core/catalog/pose_scene.h"
#include "core/io/file_bytes.h"
#include "core/mesh/gltf_document.h"
#include "core/mesh/mesh_sequence_gltf.h"
#include "core/solid/trimmed_animation.h"

#include <QTemporaryDir>
#include <QtTest>

#include <limits>
#include <stop_token>

using namespace trimlab;

namespace {

MeshAnimation foldingBox()
{
    return loadAnimation(test::testDataPath("animations/folding_box").string());
}

// The scale of `node` at time `t` under STEP interpolation of `animation` (the node's
// own scale when no channel drives it).
float scaleAt(const tinygltf::Model& model, const tinygltf::Animation& animation, int node, float t)
{
    for (const tinygltf::AnimationChannel& channel : animation.channels) {
        if (channel.target_node != node || channel.target_path != "scale")
            continue;
        const tinygltf::AnimationSampler& sampler = animation.samplers[std::size_t(channel.sampler)];
        const std::vector<float> times = test::gltfFloats(model, sampler.input);
        const std::vector<float> scales = test::gltfFloats(model, sampler.output);
        std::size_t key = 0;
        while (key + 1 < times.size() && times[key + 1] <= t)
            ++key;
        return scales[3 * key];
    }
    const std::vector<double>& scale = model.nodes[std::size_t(node)].scale;
    return scale.empty() ? 1.0f : float(scale[0]);
}

} // namespace

class TestTrimmedAnimation : public QObject {
    Q_OBJECT
private slots:
    void eachPoseIsTrimmedOnItsOwn();
    void openPoseIsNamedAndCancelStops();
    void sequenceGltfShowsOnePoseAtATime();
    void sequenceGltfKeepsAnEmptyPose();
    void sequenceGltfRefusesBadInput();

private:
    QTemporaryDir m_dir;
};

void TestTrimmedAnimation::eachPoseIsTrimmedOnItsOwn()
{
    const MeshAnimation animation = foldingBox();
    QCOMPARE(animation.poseCount(), std::size_t(3));
    TrimSettings settings;
    std::vector<std::size_t> seen;
    std::vector<std::pair<std::size_t, std::size_t>> progress;
    TaskControl control;
    control.progress = [&](const TaskProgress& p) {
        QCOMPARE(QString::fromUtf8(p.stage.data(), qsizetype(p.stage.size())), QStringLiteral("poses"));
        progress.emplace_back(p.done, p.total);
    };
    trimAnimationPoses(
        animation, 1, 2, settings,
        [&](std::size_t pose, const TrimmedSolid& solid) {
            seen.push_back(pose);
            const LoadedScene alone = animationPoseScene(animation, pose, "pose", "pose");
            const TrimmedSolid expected = trimmedSolid(alone.scene, settings);
            QCOMPARE(solid.mesh.triangles, expected.mesh.triangles);
            QCOMPARE(solid.stats.signedVolume, expected.stats.signedVolume);
            QCOMPARE(solid.stats.openEdges, std::size_t(0));
        },
        control);
    QCOMPARE(seen, (std::vector<std::size_t>{1, 2}));
    QCOMPARE(trimmedPoseName(7), std::string("pose_0007"));
    QCOMPARE(trimmedPoseName(12345), std::string("pose_12345"));
    QCOMPARE(progress, (std::vector<std::pair<std::size_t, std::size_t>>{{0, 2}, {1, 2}, {2, 2}}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, trimAnimationPoses(animation, 2, 3, settings, {}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, trimAnimationPoses(animation, 2, 1, settings, {}));
}

void TestTrimmedAnimation::openPoseIsNamedAndCancelStops()
{
    const MeshAnimation bar = loadAnimation(test::testDataPath("animations/bar").string());
    try {
        trimAnimationPoses(bar, 0, 2, TrimSettings{}, [](std::size_t, const TrimmedSolid&) {});
        QFAIL("an open animation was trimmed");
    } catch (const std::invalid_argument& e) {
        QVERIFY2(QString::fromUtf8(e.what()).startsWith(QStringLiteral("pose 0: ")) &&
                     QString::fromUtf8(e.what()).contains(QStringLiteral("--close-holes")),
                 e.what());
    }
    const MeshAnimation animation = foldingBox();
    std::stop_source stop;
    TaskControl control;
    control.stop = stop.get_token();
    std::size_t delivered = 0;
    QVERIFY_THROWS_EXCEPTION(OperationCancelled, trimAnimationPoses(
                                                     animation, 0, 2, TrimSettings{},
                                                     [&](std::size_t, const TrimmedSolid&) {
                                                         ++delivered;
                                                         stop.request_stop(); // Cancel after the first pose
                                                     },
                                                     control));
    QCOMPARE(delivered, std::size_t(1));
}

void TestTrimmedAnimation::sequenceGltfShowsOnePoseAtATime()
{
    const MeshAnimation animation = foldingBox();
    std::vector<SequenceMesh> meshes;
    trimAnimationPoses(animation, 0, 2, TrimSettings{}, [&](std::size_t pose, const TrimmedSolid& solid) {
        meshes.push_back({"pose_" + std::to_string(pose), solid.mesh});
    });
    const std::filesystem::path path = m_dir.filePath("sequence.gltf").toStdString();
    saveMeshSequenceGltf(path, meshes, 0.5, "test");
    test::requireValidGltf(path);
    QVERIFY(!QTest::currentTestFailed());
    const tinygltf::Model model =
        parseGltfDocument(io::readFileBytes(path, std::size_t(1) << 26), "sequence.gltf", path.parent_path());
    QCOMPARE(model.animations.size(), std::size_t(1));
    const tinygltf::Node& root = model.nodes[std::size_t(model.scenes.at(0).nodes.at(0))];
    QCOMPARE(root.children.size(), meshes.size());
    for (std::size_t k = 0; k < meshes.size(); ++k) {
        const int node = root.children[k];
        const tinygltf::Mesh& mesh = model.meshes[std::size_t(model.nodes[std::size_t(node)].mesh)];
        QCOMPARE(mesh.name, meshes[k].name);
        QCOMPARE(model.accessors[std::size_t(mesh.primitives.at(0).indices)].count,
                 3 * meshes[k].mesh.triangles.size());
        for (std::size_t j = 0; j < meshes.size(); ++j) {
            // At pose j's time, and just before the next pose's.
            for (const float t : {0.5f * float(j), 0.5f * float(j) + 0.49f})
                QCOMPARE(scaleAt(model, model.animations[0], node, t), j == k ? 1.0f : 0.0f);
        }
        // Without playing: the first pose only.
        const std::vector<double>& rest = model.nodes[std::size_t(node)].scale;
        QCOMPARE(rest.empty() ? 1.0 : rest[0], k == 0 ? 1.0 : 0.0);
    }
    // One mesh: no animation to play.
    const std::filesystem::path single = m_dir.filePath("single.glb").toStdString();
    saveMeshSequenceGltf(single, std::span(meshes).first(1), 0.5);
    test::requireValidGltf(single);
    QVERIFY(parseGltfDocument(io::readFileBytes(single, std::size_t(1) << 26), "single.glb", {}).animations.empty());
}

// A pose whose solid is empty (a flat pose keeps nothing) stays in the sequence as a node
// without a mesh, keyed like the others: the timing holds and nothing shows at its time.
void TestTrimmedAnimation::sequenceGltfKeepsAnEmptyPose()
{
    const MeshAnimation animation = foldingBox();
    std::vector<SequenceMesh> meshes;
    trimAnimationPoses(animation, 0, 1, TrimSettings{}, [&](std::size_t pose, const TrimmedSolid& solid) {
        meshes.push_back({"pose_" + std::to_string(pose), solid.mesh});
    });
    meshes.insert(meshes.begin() + 1, SequenceMesh{"flat", {}});
    const std::filesystem::path path = m_dir.filePath("with-empty.glb").toStdString();
    saveMeshSequenceGltf(path, meshes, 0.5);
    test::requireValidGltf(path);
    QVERIFY(!QTest::currentTestFailed());
    const tinygltf::Model model =
        parseGltfDocument(io::readFileBytes(path, std::size_t(1) << 26), "with-empty.glb", {});
    const tinygltf::Node& root = model.nodes[std::size_t(model.scenes.at(0).nodes.at(0))];
    QCOMPARE(root.children.size(), std::size_t(3));
    QCOMPARE(model.meshes.size(), std::size_t(2));
    const tinygltf::Node& flat = model.nodes[std::size_t(root.children[1])];
    QCOMPARE(flat.name, std::string("flat"));
    QCOMPARE(flat.mesh, -1);
    for (std::size_t k = 0; k < 3; ++k)
        for (std::size_t j = 0; j < 3; ++j)
            QCOMPARE(scaleAt(model, model.animations.at(0), root.children[k], 0.5f * float(j)), j == k ? 1.0f : 0.0f);
}

void TestTrimmedAnimation::sequenceGltfRefusesBadInput()
{
    const std::filesystem::path path = m_dir.filePath("bad.glb").toStdString();
    std::vector<SequenceMesh> meshes(1);
    meshes[0].name = "empty";
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, saveMeshSequenceGltf(path, {}, 0.5));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, saveMeshSequenceGltf(path, meshes, 0.5)); // only empty
    meshes[0].mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    meshes[0].mesh.triangles = {{0, 1, 3}};
    try {
        saveMeshSequenceGltf(path, meshes, 0.5);
        QFAIL("an index past the vertices was written");
    } catch (const std::invalid_argument& e) {
        QVERIFY2(QString::fromUtf8(e.what()).contains(QStringLiteral("'empty'")), e.what());
    }
    meshes[0].mesh.triangles = {{0, 1, 2}};
    meshes[0].mesh.positions[1].y = std::numeric_limits<float>::quiet_NaN();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, saveMeshSequenceGltf(path, meshes, 0.5));
    meshes[0].mesh.positions[1].y = 0.0f;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, saveMeshSequenceGltf(path, meshes, 0.0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             saveMeshSequenceGltf(m_dir.filePath("bad.obj").toStdString(), meshes, 0.5));
    QVERIFY(!std::filesystem::exists(path));
}

QTEST_GUILESS_MAIN(TestTrimmedAnimation)
#include "tst_trimmed_animation.moc"
