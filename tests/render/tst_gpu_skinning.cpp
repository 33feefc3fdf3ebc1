// GPU skinning (render/frame/gpu_skinning.h) against the CPU's skinning_reconstruction.h:
// the positions read back from the scene's buffer equal the CPU's poses within 1e-5 of the
// model's bounding-box diagonal, for LBS and DQS along both chains, in playback order and
// while scrubbing, and along a 24-pose chain; the normals equal vertexNormals of those
// positions; and a GPU-skinned self-intersecting pose trims like the exact CPU reference
// of the CPU's pose on two buffer methods. Models: four poses of the samba capture fitted
// by the fitter, and chosen transforms (antipodal dual quaternions, turns up to 150°, eight
// influences).
#include "buffer_readback.h"
#include "gl_test_context.h"
#include "method_check.h"
#include "skinning_models.h"
#include "test_paths.h"

#include "render/frame/gpu_scene.h"
#include "render/frame/gpu_skinning.h"

#include "core/skinning/seed_bones.h"
#include "core/skinning/skinning_reconstruction.h"

#include <QtTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <map>
#include <numeric>

using namespace trimlab;
using namespace trimlab::render;

namespace {

// mesh_0040, 0043, 0046, 0049 with 0043 as the rest pose: the pose-to-pose chain runs
// forward (1 → 2 → 3) and backward (1 → 0); 0046 and 0049 intersect themselves.
const char* const kSambaPattern = "anim/samba/mesh_004?.obj.gz";
const std::vector<std::size_t> kSambaPoses{0, 3, 6, 9};
constexpr std::size_t kSambaRest = 1;
constexpr std::size_t kBones = 12;

struct ModelCase {
    QString name;
    bool fitted = true; // else chosen transforms
    SkinningMethod method = SkinningMethod::Lbs;
    SkinningChain chain = SkinningChain::PoseToPose;
    std::size_t influences = 4; // chosen transforms only
};

std::vector<ModelCase> modelCases()
{
    using M = SkinningMethod;
    using C = SkinningChain;
    return {
        {"fitted LBS pose-to-pose", true, M::Lbs, C::PoseToPose},
        {"fitted LBS rest-to-pose", true, M::Lbs, C::RestToPose},
        {"fitted DQS pose-to-pose", true, M::Dqs, C::PoseToPose},
        {"fitted DQS rest-to-pose", true, M::Dqs, C::RestToPose},
        {"chosen DQS rest-to-pose, antipodal, 8 influences", false, M::Dqs, C::RestToPose, 8},
        {"chosen DQS pose-to-pose, antipodal, 4 influences", false, M::Dqs, C::PoseToPose, 4},
        {"chosen LBS pose-to-pose, 8 influences", false, M::Lbs, C::PoseToPose, 8},
        {"chosen LBS rest-to-pose, 3 influences", false, M::Lbs, C::RestToPose, 3},
    };
}

// Playback in chainOrder (one step per pose), the same pose again (a copy), then jumps:
// back towards the rest pose (a restart), far ahead, across the rest pose and back.
std::vector<std::size_t> visitOrder(const SkinningModel& model)
{
    std::vector<std::size_t> order = chainOrder(model.poseCount(), model.restPose);
    const std::size_t last = model.poseCount() - 1;
    order.insert(order.end(), {0, 0, last, model.restPose, 0, last - 1, last, model.restPose + 1, 0});
    return order;
}

using test::largestDistance;

TriangleMesh poseMesh(const SkinningModel& model, const PosePositions& pose)
{
    TriangleMesh mesh;
    mesh.positions.assign(pose.begin(), pose.end());
    mesh.triangles = model.triangles;
    return mesh;
}

Scene sceneOf(TriangleMesh mesh)
{
    Scene scene;
    scene.objects.push_back(SceneObject{"skinned", std::move(mesh), glm::dmat4(1.0)});
    return scene;
}

} // namespace

Q_DECLARE_METATYPE(ModelCase)
Q_DECLARE_METATYPE(trimlab::render::FragmentMethodKind)

class TestGpuSkinning : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void positionsAndNormalsMatchCpu_data();
    void positionsAndNormalsMatchCpu();
    void playbackStepsOnePosePerPose();
    void longChainsDoNotDrift();
    void trimMatchesReference_data();
    void trimMatchesReference();
    void refusesMismatchedObjects();

private:
    const SkinningModel& model(const ModelCase& c);

    std::unique_ptr<OffscreenGlContext> m_context;
    std::unique_ptr<TrimRenderer> m_renderer;
    MeshAnimation m_samba;
    std::map<QString, SkinningModel> m_models;
};

void TestGpuSkinning::initTestCase()
{
    TRIMLAB_INIT_GL_CONTEXT(m_context);
    const std::filesystem::path samba = test::sharedDataPath("anim/samba");
    if (!std::filesystem::exists(samba))
        QSKIP(qPrintable("shared data missing: " + QString::fromStdString(samba.string())));
    m_samba = test::selectedPoses(test::sharedDataPath(kSambaPattern).string(), kSambaPoses, kSambaRest);
    m_renderer = std::make_unique<TrimRenderer>(m_context->context());
}

const SkinningModel& TestGpuSkinning::model(const ModelCase& c)
{
    auto it = m_models.find(c.name);
    if (it == m_models.end()) {
        SkinningModel made = c.fitted ? seedBoneModel(m_samba, kBones, c.method, c.chain)
                                      : test::chosenTransformModel(m_samba, kBones, c.influences, c.method, c.chain, 5,
                                                                   19u + unsigned(c.influences));
        it = m_models.emplace(c.name, std::move(made)).first;
    }
    return it->second;
}

void TestGpuSkinning::positionsAndNormalsMatchCpu_data()
{
    QTest::addColumn<ModelCase>("modelCase");
    for (const ModelCase& c : modelCases())
        QTest::newRow(qPrintable(c.name)) << c;
}

void TestGpuSkinning::positionsAndNormalsMatchCpu()
{
    QFETCH(ModelCase, modelCase);
    const SkinningModel& skinned = model(modelCase);
    const std::vector<PosePositions> cpu = reconstructPoses(skinned);
    const double diagonal = 2.0 * computeBounds(poseMesh(skinned, skinned.restPositions)).radius();
    QVERIFY(diagonal > 0.0);

    m_renderer->setScene(sceneOf(poseMesh(skinned, skinned.restPositions)));
    GpuScene& scene = m_renderer->gpuScene();
    GpuSkinning skinning(m_renderer->gl(), skinned);
    double worstPosition = 0.0;
    double worstNormal = 0.0;
    double largestMotion = 0.0; // non-vacuous: the poses move
    for (std::size_t pose : visitOrder(skinned)) {
        skinning.skinPose(scene, 0, pose);
        const std::vector<glm::vec3> positions = scene.readPositions(0);
        const double distance = largestDistance(positions, cpu[pose]);
        QVERIFY2(distance <= 1e-5 * diagonal,
                 qPrintable(QString("pose %1: GPU positions differ from the CPU's by %2 (diagonal %3)")
                                .arg(pose)
                                .arg(distance)
                                .arg(diagonal)));
        const std::vector<glm::vec3> normals = scene.readNormals(0);
        const std::vector<glm::vec3> expected = vertexNormals(TriangleMesh{positions, skinned.triangles});
        const double normalError = largestDistance(normals, expected);
        // The GPU's angles are double-precision too (vertex_normals.comp), so the normals
        // agree to float rounding even where a crumpled vertex's face normals nearly cancel.
        QVERIFY2(normalError <= 1e-6,
                 qPrintable(QString("pose %1: GPU normals differ by %2").arg(pose).arg(normalError)));
        worstPosition = std::max(worstPosition, distance / diagonal);
        worstNormal = std::max(worstNormal, normalError);
        largestMotion = std::max(largestMotion, largestDistance(positions, skinned.restPositions));
    }
    QVERIFY2(largestMotion > 0.05 * diagonal, "the poses hardly move: the comparison says little");
    qInfo("%zu vertices, %zu bones, %zu poses: worst position error %.3g of the diagonal, worst normal error %.3g",
          skinned.vertexCount(), skinned.boneCount(), skinned.poseCount(), worstPosition, worstNormal);
}

// Playback walks the pose-to-pose chain one step per pose; a pose behind the held one
// restarts at the rest pose; the held pose again is a copy.
void TestGpuSkinning::playbackStepsOnePosePerPose()
{
    const SkinningModel& skinned = model(modelCases().front());
    QCOMPARE(skinned.chain, SkinningChain::PoseToPose);
    m_renderer->setScene(sceneOf(poseMesh(skinned, skinned.restPositions)));
    GpuSkinning skinning(m_renderer->gl(), skinned);
    for (std::size_t pose : chainOrder(skinned.poseCount(), skinned.restPose)) {
        skinning.skinPose(m_renderer->gpuScene(), 0, pose);
        QCOMPARE(skinning.lastStepCount(), pose == skinned.restPose ? 0u : 1u);
        QCOMPARE(skinning.chainPose(), std::optional<std::size_t>(pose));
    }
    skinning.skinPose(m_renderer->gpuScene(), 0, 0);
    QCOMPARE(skinning.lastStepCount(), 0u);
    skinning.skinPose(m_renderer->gpuScene(), 0, skinned.poseCount() - 1); // across the rest pose
    QCOMPARE(skinning.lastStepCount(), skinned.poseCount() - 1 - skinned.restPose);
}

// The first 24 poses of samba fitted pose-to-pose: 23 chain steps in playback, each pose's
// GPU positions still within the bar of the CPU's (the chain state is double precision).
void TestGpuSkinning::longChainsDoNotDrift()
{
    std::vector<std::size_t> first24(24);
    std::iota(first24.begin(), first24.end(), std::size_t(0));
    const MeshAnimation samba =
        test::selectedPoses(test::sharedDataPath("anim/samba/mesh_00??.obj.gz").string(), first24, 0);
    for (SkinningMethod method : {SkinningMethod::Lbs, SkinningMethod::Dqs}) {
        const SkinningModel skinned = seedBoneModel(samba, kBones, method, SkinningChain::PoseToPose);
        const std::vector<PosePositions> cpu = reconstructPoses(skinned);
        const double diagonal = 2.0 * computeBounds(poseMesh(skinned, skinned.restPositions)).radius();
        m_renderer->setScene(sceneOf(poseMesh(skinned, skinned.restPositions)));
        GpuSkinning skinning(m_renderer->gl(), skinned);
        double worst = 0.0;
        for (std::size_t pose : chainOrder(skinned.poseCount(), skinned.restPose)) {
            skinning.skinPose(m_renderer->gpuScene(), 0, pose);
            const double distance = largestDistance(m_renderer->gpuScene().readPositions(0), cpu[pose]);
            QVERIFY2(distance <= 1e-5 * diagonal, qPrintable(QString("pose %1 differs by %2").arg(pose).arg(distance)));
            worst = std::max(worst, distance / diagonal);
        }
        qInfo("%s, 24 poses: worst position error %.3g of the diagonal", method == SkinningMethod::Lbs ? "LBS" : "DQS",
              worst);
    }
}

void TestGpuSkinning::trimMatchesReference_data()
{
    QTest::addColumn<ModelCase>("modelCase");
    QTest::addColumn<FragmentMethodKind>("method");
    const std::vector<ModelCase> cases = modelCases();
    for (const ModelCase& c : {cases[0], cases[3], cases[4], cases[6]})
        for (FragmentMethodKind method : {FragmentMethodKind::KPlusArray, FragmentMethodKind::ABufferLinkedList})
            QTest::newRow(qPrintable(QString("%1: %2").arg(QString::fromLatin1(methodInfo(method).id.data()), c.name)))
                << c << method;
}

// Pose 2 (mesh_0046, self-intersecting; crumpled under the chosen transforms) GPU-skinned,
// trimmed by the GPU, against the exact reference of the CPU's pose.
void TestGpuSkinning::trimMatchesReference()
{
    QFETCH(ModelCase, modelCase);
    QFETCH(FragmentMethodKind, method);
    const SkinningModel& skinned = model(modelCase);
    constexpr std::size_t kPose = 2;
    const Scene cpuScene = sceneOf(poseMesh(skinned, reconstructPose(skinned, kPose)));
    const ReferenceRenderer reference(cpuScene);

    m_renderer->setScene(sceneOf(poseMesh(skinned, skinned.restPositions)));
    GpuSkinning skinning(m_renderer->gl(), skinned);
    skinning.skinPose(m_renderer->gpuScene(), 0, kPose);

    const Bounds bounds = cpuScene.worldBounds();
    test::MethodCase testCase{QTest::currentDataTag(), {}, {}, {}, 256, 192};
    Camera camera = fitCamera(bounds, 256.0 / 192.0, glm::dvec3(-0.3, -0.2, -1.0));
    camera.eye = camera.target + (camera.eye - camera.target) * 0.6; // the dancer is slim: closer
    testCase.camera = withDepthRange(camera, bounds);
    testCase.settings.trimEnabled = true;
    testCase.settings.rule = StaticRule::AlternatingBorder;
    const ReferenceResult expected = reference.render(testCase.camera, 256, 192, testCase.settings);
    QString summary;
    const auto failure =
        test::checkMethodAgainstReference(*m_renderer, method, testCase, reference, expected, &summary);
    qInfo("%s", qPrintable(summary));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
}

void TestGpuSkinning::refusesMismatchedObjects()
{
    const SkinningModel& skinned = model(modelCases().front());
    m_renderer->setScene(sceneOf(poseMesh(skinned, skinned.restPositions)));
    GpuSkinning skinning(m_renderer->gl(), skinned);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, skinning.skinPose(m_renderer->gpuScene(), 0, skinned.poseCount()));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, skinning.skinPose(m_renderer->gpuScene(), 1, 0));
    TriangleMesh other = poseMesh(skinned, skinned.restPositions);
    other.triangles.pop_back();
    m_renderer->setScene(sceneOf(other));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, skinning.skinPose(m_renderer->gpuScene(), 0, 0));
}

QTEST_MAIN(TestGpuSkinning)
#include "tst_gpu_skinning.moc"
