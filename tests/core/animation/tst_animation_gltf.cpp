// glTF 2.0 animations sampled into poses: morph targets (LINEAR and STEP weights),
// linear blend skinning with inverse bind matrices, keyframe vs fixed-rate sampling, the
// cubic spline interpolation, and load errors. The expected positions are worked out by
// hand from the motions tests/data/make_animation_files.py describes.
#include "core/animation/gltf_animation.h"
#include "core/animation/gltf_keyframes.h"
#include "core/mesh/mesh_load_error.h"
#include "core/skinning/file_skin_model.h"
#include "core/skinning/skinning_reconstruction.h"

#include "test_paths.h"

#include <QtTest>

#include <glm/geometric.hpp>

#include <cmath>

using namespace trimlab;
using trimlab::test::testDataPath;

namespace {

std::filesystem::path animationFile(const std::string& name)
{
    return testDataPath("animations/" + name);
}

bool near(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-6f)
{
    return std::abs(a.x - b.x) <= tolerance && std::abs(a.y - b.y) <= tolerance && std::abs(a.z - b.z) <= tolerance;
}

QString text(const glm::vec3& v)
{
    return QStringLiteral("(%1, %2, %3)").arg(v.x).arg(v.y).arg(v.z);
}

} // namespace

class TestAnimationGltf : public QObject {
    Q_OBJECT
private slots:
    void morphTargetAtKeyframes();
    void morphTargetAtFixedRate();
    void stepInterpolation();
    void skinnedAtKeyframes();
    void skinnedHalfway();
    void skinnedFileKeepsItsSkin();
    void cubicSplineInterpolation();
    void errors();
};

// Vertex 2 of the unit square is lifted by the morph weight: 0, 1, 0.5 at t = 0, 1, 2 s.
void TestAnimationGltf::morphTargetAtKeyframes()
{
    const MeshAnimation a = loadGltfAnimation(animationFile("morph_square.gltf"));
    QCOMPARE(a.poseCount(), std::size_t(3));
    QCOMPARE(a.vertexCount(), std::size_t(4));
    QCOMPARE(a.triangleCount(), std::size_t(2));
    QCOMPARE(a.poseTimes, (std::vector<double>{0.0, 1.0, 2.0}));
    QCOMPARE(a.poseNames[1], std::string("lift t=1.000 s"));
    QCOMPARE(a.poses[0][2], glm::vec3(1, 1, 0));
    QCOMPARE(a.poses[1][2], glm::vec3(1, 1, 1));
    QCOMPARE(a.poses[2][2], glm::vec3(1, 1, 0.5f));
    QCOMPARE(a.poses[2][1], glm::vec3(1, 0, 0)); // not in the target
}

// At 4 fps over [0, 2] s: 9 poses; linear weights 0.25 at t = 0.25 and 0.75 at t = 1.5.
void TestAnimationGltf::morphTargetAtFixedRate()
{
    GltfAnimationOptions options;
    options.fps = 4.0;
    const MeshAnimation a = loadGltfAnimation(animationFile("morph_square.gltf"), options);
    QCOMPARE(a.poseCount(), std::size_t(9));
    QCOMPARE(a.poseTimes[1], 0.25);
    QVERIFY(near(a.poses[1][2], {1, 1, 0.25f}));
    QVERIFY(near(a.poses[6][2], {1, 1, 0.75f}));
    QVERIFY(near(a.poses[8][2], {1, 1, 0.5f}));
}

// Animation 1 holds 0.2 until t = 1 s, then 0.8 (STEP); sampled at 2 fps: t = 0, 0.5, 1.
void TestAnimationGltf::stepInterpolation()
{
    GltfAnimationOptions options;
    options.animation = 1;
    options.fps = 2.0;
    const MeshAnimation a = loadGltfAnimation(animationFile("morph_square.gltf"), options);
    QCOMPARE(a.poseCount(), std::size_t(3));
    QVERIFY(near(a.poses[0][2], {1, 1, 0.2f}));
    QVERIFY(near(a.poses[1][2], {1, 1, 0.2f}));
    QVERIFY(near(a.poses[2][2], {1, 1, 0.8f}));
    QCOMPARE(a.poseNames[0], std::string("steps t=0.000 s"));
}

// Joint j1 (at x = 1) turns 90° about +z. Its joint matrix is T(1)·Rz(90°)·T(−1) (world ×
// inverse bind), j0's is the identity:
//   x = 2 vertices follow j1:  (2,0,0) → (1,1,0),  (2,1,0) → (0,1,0);
//   x = 1 vertices blend half-half: (1,0,0) → (1,0,0), (1,1,0) → ((1,1,0) + (0,0,0))/2;
//   x = 0 vertices stay. The mesh node's own translation (+5 in x) is ignored (skinned).
// Vertices 3 and 5 meet at (0,1,0) in the bent pose but not at rest: they stay apart.
void TestAnimationGltf::skinnedAtKeyframes()
{
    const MeshAnimation a = loadGltfAnimation(animationFile("skinned_bar.gltf"));
    QCOMPARE(a.poseCount(), std::size_t(2));
    QCOMPARE(a.vertexCount(), std::size_t(6));
    const std::vector<glm::vec3> rest = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
    const std::vector<glm::vec3> bent = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 0.5f, 0}, {0, 1, 0}};
    for (std::size_t v = 0; v < 6; ++v) {
        QVERIFY2(near(a.poses[0][v], rest[v]),
                 qPrintable(QStringLiteral("rest %1: %2").arg(v).arg(text(a.poses[0][v]))));
        QVERIFY2(near(a.poses[1][v], bent[v]),
                 qPrintable(QStringLiteral("bent %1: %2").arg(v).arg(text(a.poses[1][v]))));
    }
}

// Halfway (t = 0.5 s at 2 fps) slerp gives 45°: (2,0,0) → (1 + √½, √½, 0).
void TestAnimationGltf::skinnedHalfway()
{
    GltfAnimationOptions options;
    options.fps = 2.0;
    const MeshAnimation a = loadGltfAnimation(animationFile("skinned_bar.gltf"), options);
    QCOMPARE(a.poseCount(), std::size_t(3));
    const float s = float(std::sqrt(0.5));
    QVERIFY2(near(a.poses[1][2], {1 + s, s, 0}), qPrintable(text(a.poses[1][2])));
}

// The skin that posed skinned_bar.gltf stays beside the poses (at 4 fps, 5 poses), and as
// a rest-to-pose LBS model (the GPU skinning's input) it gives the sampled poses back;
// files without a skin, and an animation whose poses were dropped, have none.
void TestAnimationGltf::skinnedFileKeepsItsSkin()
{
    GltfAnimationOptions options;
    options.fps = 4.0;
    MeshAnimation a = loadGltfAnimation(animationFile("skinned_bar.gltf"), options);
    QVERIFY(a.skin);
    QCOMPARE(a.skin->jointCount, std::size_t(2));
    QCOMPARE(a.skin->bindPositions.size(), a.vertexCount());
    QCOMPARE(a.skin->jointMatrices.size(), a.poseCount());
    const std::optional<SkinningModel> model = fileSkinningModel(a);
    QVERIFY(model);
    QVERIFY(restPoseMoves(*model) || model->affine[a.restPose] == std::vector<Affine3>(2));
    const std::vector<PosePositions> skinned = reconstructPoses(*model);
    QCOMPARE(skinned.size(), a.poseCount());
    double largest = 0.0;
    double motion = 0.0; // non-vacuous: the bar bends
    for (std::size_t t = 0; t < a.poseCount(); ++t)
        for (std::size_t v = 0; v < a.vertexCount(); ++v) {
            largest = std::max(largest, glm::length(skinned[t][v] - glm::dvec3(a.poses[t][v])));
            motion = std::max(motion, glm::length(glm::dvec3(a.poses[t][v] - a.poses[0][v])));
        }
    QVERIFY2(largest < 1e-6, qPrintable(QString::number(largest)));
    QVERIFY(motion > 1.0);

    a.poses.pop_back();
    QVERIFY(!fileSkinningModel(a));
    QVERIFY(!loadGltfAnimation(animationFile("morph_square.gltf")).skin);
}

// Hermite on [0, 2] with v0 = 0, out-tangent 1, v1 = 1, in-tangent 0, at s = ½:
// h00·v0 + h10·Δ·out0 + h01·v1 + h11·Δ·in1 = 0 + (1/8)·2·1 + (1/2)·1 + 0 = 0.75.
void TestAnimationGltf::cubicSplineInterpolation()
{
    KeyframeTrack track;
    track.times = {0.0, 2.0};
    track.components = 1;
    track.interpolation = KeyframeInterpolation::CubicSpline;
    track.values = {0.0, 0.0, 1.0, /* key 1: */ 0.0, 1.0, 0.0};
    QCOMPARE(track.sample(1.0).at(0), 0.75);
    QCOMPARE(track.sample(-1.0).at(0), 0.0); // clamped before the first key
    QCOMPARE(track.sample(5.0).at(0), 1.0);  // and after the last
}

void TestAnimationGltf::errors()
{
    auto message = [](const std::filesystem::path& path, GltfAnimationOptions options) {
        try {
            (void)loadGltfAnimation(path, options);
        } catch (const MeshLoadError& e) {
            return QString::fromStdString(e.what());
        }
        return QString();
    };
    GltfAnimationOptions options;
    options.animation = 5;
    QVERIFY(
        message(animationFile("morph_square.gltf"), options).contains("animation 5 does not exist (the file has 2)"));
    QVERIFY(message(testDataPath("meshes/two_nodes.gltf"), {}).contains("the file has no animations"));
    QVERIFY(message(animationFile("missing.gltf"), {}).contains("missing.gltf"));
    options = {};
    options.fps = -1.0;
    QVERIFY(message(animationFile("morph_square.gltf"), options).contains("frame rate"));
}

QTEST_GUILESS_MAIN(TestAnimationGltf)
#include "tst_animation_gltf.moc"
