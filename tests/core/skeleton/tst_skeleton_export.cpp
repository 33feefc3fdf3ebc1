// The rigged glTF export (Khronos validator, re-import through the project's own glTF
// animation reader) and the skeleton JSON file (round trip, errors naming the JSON path).
#include "core/skeleton/bone_heat_weights.h"
#include "core/skeleton/rig_validation.h"
#include "core/skeleton/rigged_gltf.h"
#include "core/skeleton/skeleton_json.h"
#include "core/skeleton/skeleton_pose.h"

#include "core/animation/gltf_animated_geometry.h"
#include "core/animation/gltf_animation.h"
#include "core/animation/gltf_node_transforms.h"
#include "core/mesh/gltf_document.h"

#include "gltf_validation.h"
#include "skeleton_rig_fixtures.h"

#include <QTemporaryDir>
#include <QtTest>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

using namespace trimlab;

namespace {

std::string readAll(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

std::map<int, double> influences(const std::array<int, kBoneInfluences>& bones,
                                 const std::array<float, kBoneInfluences>& weights)
{
    std::map<int, double> result;
    for (std::size_t k = 0; k < kBoneInfluences; ++k)
        if (weights[k] > 0.0f)
            result[bones[k]] += weights[k];
    return result;
}

// The where() of the SkeletonFileError that parsing `text` throws, or "no error".
QString errorPath(const std::string& text, QString* message = nullptr)
{
    try {
        (void)parseSkeletonJson(text, "rig.json");
    } catch (const SkeletonFileError& error) {
        if (message)
            *message = QString::fromStdString(error.what());
        return QString::fromStdString(error.where());
    }
    return QStringLiteral("no error");
}

std::string replaced(std::string text, const std::string& from, const std::string& to)
{
    const std::size_t at = text.find(from);
    if (at == std::string::npos)
        throw std::logic_error("test text lacks '" + from + "'");
    return text.replace(at, from.size(), to);
}

} // namespace

class TestSkeletonExport : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void boneOrientationPointsYAlongTheBone();
    void glbPassesTheValidator();
    void gltfReimportsWithTheSameJointsAndWeights();
    void posedExportPlaysTheSkinnedPose();
    void awkwardWeightsAreNormalisedForTheValidator();
    void badInputIsRefused();
    void jsonRoundTripIsExact();
    void malformedJsonNamesThePath();
    void rigValidationNamesTheField();

private:
    QTemporaryDir m_dir;
    TriangleMesh m_t;
    SkeletonRig m_rig;
    BoneWeights m_weights;
};

void TestSkeletonExport::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_t = test::makeTTube();
    m_rig = test::tRig();
    // A deeper hierarchy than the T's three root bones: split the right arm in two.
    m_rig.joints.push_back({2.75, 1.0, 1.0});
    m_rig.parent = {-1, 0, 4, 0, 0};
    m_rig.bones = {{0, 1, -1}, {0, 4, -1}, {0, 3, -1}, {4, 2, 1}};
    QVERIFY(!findRigProblem(m_rig).has_value());
    m_weights = boneHeatWeights(m_t, m_rig);
}

void TestSkeletonExport::boneOrientationPointsYAlongTheBone()
{
    const glm::dvec3 head(1.0, 2.0, 3.0);
    for (const glm::dvec3& d : {glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0),
                                glm::dvec3(0.3, -0.9, 0.2), glm::dvec3(0, 0, -2)}) {
        const glm::dquat q = boneOrientation(head, head + d);
        QVERIFY(std::abs(glm::length(q) - 1.0) < 1e-12);
        QVERIFY(glm::length(q * glm::dvec3(0, 1, 0) - glm::normalize(d)) < 1e-12);
    }
    const glm::dquat none = boneOrientation(head, head);
    QCOMPARE(none, glm::dquat(1.0, 0.0, 0.0, 0.0));
}

void TestSkeletonExport::glbPassesTheValidator()
{
    const std::filesystem::path path = m_dir.filePath("t.glb").toStdString();
    exportRiggedGltf(m_t, m_rig, m_weights, path);
    QVERIFY(readAll(path).rfind("glTF", 0) == 0);
    test::requireValidGltf(path);
}

void TestSkeletonExport::gltfReimportsWithTheSameJointsAndWeights()
{
    const std::filesystem::path path = m_dir.filePath("t.gltf").toStdString();
    exportRiggedGltf(m_t, m_rig, m_weights, path);
    test::requireValidGltf(path);
    QVERIFY(!QTest::currentTestFailed());
    const tinygltf::Model model = parseGltfDocument(readAll(path), "t.gltf", path.parent_path());
    const std::vector<int> parents = nodeParents(model, "t.gltf");
    const GltfAnimatedGeometry geometry = readAnimatedGeometry(model, parents, "t.gltf");
    QCOMPARE(geometry.skins.size(), std::size_t(1));
    const GltfSkin& skin = geometry.skins[0];
    // One joint per bone, then the root joint; the root is the skin's skeleton and a
    // scene root, and every ancestor of a joint is a joint (Blender turns the transform
    // of a non-joint ancestor into a pose on the root bones).
    QCOMPARE(skin.joints.size(), m_rig.bones.size() + 1);
    const int skeleton = model.skins[0].skeleton;
    QCOMPARE(int(skin.joints.back()), skeleton);
    QCOMPARE(parents[std::size_t(skeleton)], -1);
    for (const std::size_t joint : skin.joints)
        for (int up = parents[joint]; up >= 0; up = parents[std::size_t(up)])
            QVERIFY2(std::find(skin.joints.begin(), skin.joints.end(), std::size_t(up)) != skin.joints.end(),
                     qPrintable(QString("node %1 above joint %2 is not a joint").arg(up).arg(joint)));
    // The hierarchy: joint b's node is a child of its parent bone's node, or of the
    // root joint for bones that start at the root joint.
    for (std::size_t b = 0; b < m_rig.bones.size(); ++b) {
        const int parentBone = m_rig.bones[b].parentBone;
        const int expected = parentBone < 0 ? skeleton : int(skin.joints[std::size_t(parentBone)]);
        QCOMPARE(parents[skin.joints[b]], expected);
    }
    // Every joint node sits at its bone's head and its +Y points at the tail.
    const std::vector<NodeTransform> nodes = fileNodeTransforms(model, "t.gltf");
    const std::vector<glm::dmat4> world = worldMatrices(nodes, parents);
    for (std::size_t b = 0; b < m_rig.bones.size(); ++b) {
        const glm::dmat4& m = world[skin.joints[b]];
        const glm::dvec3 head = m_rig.joints[std::size_t(m_rig.bones[b].head)];
        const glm::dvec3 tail = m_rig.joints[std::size_t(m_rig.bones[b].tail)];
        QVERIFY(glm::length(glm::dvec3(m[3]) - head) < 1e-5);
        QVERIFY(glm::length(glm::dvec3(m[1]) - glm::normalize(tail - head)) < 1e-6);
    }
    // The weights, vertex by vertex, and the bind pose is the rest mesh.
    QCOMPARE(geometry.vertexCount, m_t.vertexCount());
    const GltfPrimitiveInstance& primitive = geometry.primitives[0];
    QCOMPARE(primitive.influences, kBoneInfluences);
    for (std::size_t v = 0; v < m_t.vertexCount(); ++v) {
        std::array<int, kBoneInfluences> bones{};
        std::array<float, kBoneInfluences> weights{};
        for (std::size_t k = 0; k < kBoneInfluences; ++k) {
            bones[k] = int(primitive.joints[v * kBoneInfluences + k]);
            weights[k] = float(primitive.weights[v * kBoneInfluences + k]);
        }
        const std::map<int, double> read = influences(bones, weights);
        const std::map<int, double> original = influences(m_weights.bones[v], m_weights.weights[v]);
        QCOMPARE(read.size(), original.size());
        for (const auto& [bone, w] : original)
            QVERIFY2(read.count(bone) && std::abs(read.at(bone) - w) < 1e-6, qPrintable(QString("vertex %1").arg(v)));
    }
    // The file's pose is the bind pose: every joint matrix is the identity.
    for (const glm::dmat4& m : jointMatrices(skin, world))
        for (int c = 0; c < 4; ++c)
            QVERIFY(glm::length(m[c] - glm::dmat4(1.0)[c]) < 1e-5);
    const glm::dvec3 rootAt = glm::dvec3(world[std::size_t(skeleton)][3]);
    QVERIFY(glm::length(rootAt - m_rig.joints[std::size_t(m_rig.root)]) < 1e-5);
    const std::vector<glm::dvec3> bind = geometry.pose(nodes, world);
    for (std::size_t v = 0; v < m_t.vertexCount(); ++v)
        QVERIFY(glm::length(bind[v] - glm::dvec3(m_t.positions[v])) < 1e-5);
}

void TestSkeletonExport::posedExportPlaysTheSkinnedPose()
{
    SkeletonPose pose = restPose(m_rig);
    pose.rotations[1] = glm::angleAxis(M_PI / 2.0, glm::dvec3(0.0, 0.0, 1.0));
    pose.rotations[3] = glm::angleAxis(-M_PI / 3.0, glm::dvec3(0.0, 0.0, 1.0)); // the forearm bends back
    pose.rotations[2] = glm::angleAxis(0.4, glm::normalize(glm::dvec3(1.0, 0.0, 1.0)));
    pose.rootTranslation = {0.5, 0.0, -0.25};
    const std::filesystem::path path = m_dir.filePath("posed.glb").toStdString();
    RiggedGltfOptions options;
    options.pose = &pose;
    exportRiggedGltf(m_t, m_rig, m_weights, path, options);
    test::requireValidGltf(path);
    QVERIFY(!QTest::currentTestFailed());
    const MeshAnimation animation = loadGltfAnimation(path);
    QCOMPARE(animation.poseCount(), std::size_t(2));
    QCOMPARE(animation.vertexCount(), m_t.vertexCount());
    QCOMPARE(animation.triangles, m_t.triangles);
    const std::vector<glm::vec3> expected = posePositions(m_t.positions, m_rig, m_weights, pose, SkinningMethod::Lbs);
    double worst0 = 0.0, worst1 = 0.0;
    for (std::size_t v = 0; v < m_t.vertexCount(); ++v) {
        worst0 = std::max(worst0, double(glm::length(animation.poses[0][v] - m_t.positions[v])));
        worst1 = std::max(worst1, double(glm::length(animation.poses[1][v] - expected[v])));
    }
    // Float node transforms and matrices over a 12-unit model: a few 1e-6.
    QVERIFY2(worst0 < 2e-5, qPrintable(QString::number(worst0)));
    QVERIFY2(worst1 < 2e-5, qPrintable(QString::number(worst1)));
}

void TestSkeletonExport::awkwardWeightsAreNormalisedForTheValidator()
{
    // Thirds, tenths, a tiny weight, and weights that sum to 0.8 or 1.25 (hand-made or
    // rounded elsewhere): the validator's float sum must come out 1 within 2e-7 per weight.
    BoneWeights w;
    for (std::size_t v = 0; v < m_t.vertexCount(); ++v) {
        switch (v % 5) {
        case 0:
            w.bones.push_back({0, 1, 2, -1});
            w.weights.push_back({1 / 3.0f, 1 / 3.0f, 1 / 3.0f, 0.0f});
            break;
        case 1:
            w.bones.push_back({3, 0, 2, 1});
            w.weights.push_back({0.7f, 0.1f, 0.1f, 0.1f});
            break;
        case 2:
            w.bones.push_back({2, 1, -1, -1});
            w.weights.push_back({0.9999999f, 1e-7f, 0.0f, 0.0f});
            break;
        case 3:
            w.bones.push_back({1, 0, -1, -1});
            w.weights.push_back({0.5f, 0.3f, 0.0f, 0.0f});
            break;
        default:
            w.bones.push_back({1, 0, 3, 2});
            w.weights.push_back({0.5f, 0.25f, 0.25f, 0.25f});
            break;
        }
    }
    const std::filesystem::path path = m_dir.filePath("awkward.glb").toStdString();
    exportRiggedGltf(m_t, m_rig, w, path);
    test::requireValidGltf(path);
    QVERIFY(!QTest::currentTestFailed());
    // The ratios survive: 0.5 : 0.3 is written as 0.625 : 0.375.
    const tinygltf::Model model = parseGltfDocument(readAll(path), "awkward.glb", {});
    const GltfAnimatedGeometry geometry = readAnimatedGeometry(model, nodeParents(model, "a"), "a");
    const GltfPrimitiveInstance& primitive = geometry.primitives[0];
    QCOMPARE(primitive.joints[3 * kBoneInfluences], std::uint32_t(1));
    QCOMPARE(primitive.weights[3 * kBoneInfluences], double(0.625f));
    QCOMPARE(primitive.weights[3 * kBoneInfluences + 1], double(0.375f));
}

void TestSkeletonExport::badInputIsRefused()
{
    BoneWeights fewer = m_weights;
    fewer.bones.pop_back();
    fewer.weights.pop_back();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)riggedGltf(m_t, m_rig, fewer, true));
    BoneWeights outOfRange = m_weights;
    outOfRange.bones[5][0] = 9;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)riggedGltf(m_t, m_rig, outOfRange, true));
    BoneWeights none = m_weights;
    none.weights[7] = {0.0f, 0.0f, 0.0f, 0.0f};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)riggedGltf(m_t, m_rig, none, true));
    SkeletonRig bad = m_rig;
    bad.parent[2] = 2;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)riggedGltf(m_t, bad, m_weights, true));
    TriangleMesh nan = m_t;
    nan.positions[3].y = std::nanf("");
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)riggedGltf(nan, m_rig, m_weights, true));
}

void TestSkeletonExport::jsonRoundTripIsExact()
{
    SkeletonRig rig = m_rig;
    rig.joints[1] = {-5.5 + 1e-13, 1.0 / 3.0, 0.1}; // doubles that need all 17 digits
    rig.vertexJoint.assign(m_t.vertexCount(), 0);
    for (std::size_t v = 0; v < rig.vertexJoint.size(); ++v)
        rig.vertexJoint[v] = int(v % rig.joints.size());
    CurveSkeleton curve;
    curve.nodes = {{0, 1, 1}, {-3, 1, 1}, {3, 1, 1}, {0, -3, 1}, {-5.5, 1, 1}};
    curve.edges = {{0, 1}, {0, 2}, {0, 3}, {1, 4}};
    curve.vertexNode.assign(m_t.vertexCount(), 4);
    const std::filesystem::path path = m_dir.filePath("rig.json").toStdString();
    saveSkeletonJson(path, rig, &curve);
    const SkeletonDocument read = loadSkeletonJson(path);
    QCOMPARE(read.rig.joints, rig.joints);
    QCOMPARE(read.rig.parent, rig.parent);
    QCOMPARE(read.rig.root, rig.root);
    QCOMPARE(read.rig.vertexJoint, rig.vertexJoint);
    QCOMPARE(read.rig.bones.size(), rig.bones.size());
    for (std::size_t b = 0; b < rig.bones.size(); ++b) {
        QCOMPARE(read.rig.bones[b].head, rig.bones[b].head);
        QCOMPARE(read.rig.bones[b].tail, rig.bones[b].tail);
        QCOMPARE(read.rig.bones[b].parentBone, rig.bones[b].parentBone);
    }
    QVERIFY(read.curve.has_value());
    QCOMPARE(read.curve->nodes, curve.nodes);
    QCOMPARE(read.curve->edges, curve.edges);
    QCOMPARE(read.curve->vertexNode, curve.vertexNode);
    // Without a curve skeleton the field is absent and comes back empty.
    QVERIFY(!parseSkeletonJson(skeletonJson(rig), "x").curve.has_value());
}

void TestSkeletonExport::malformedJsonNamesThePath()
{
    const std::string good = skeletonJson(m_rig);
    QCOMPARE(errorPath(good), QStringLiteral("no error"));
    QString message;
    QCOMPARE(errorPath(good.substr(0, good.size() / 2), &message), QString());
    QVERIFY2(message.startsWith("rig.json: truncated JSON at line"), qPrintable(message));
    QCOMPARE(errorPath(replaced(good, "\"head\": 0", "\"head\": 2"), &message), QStringLiteral("bones[0].head"));
    QVERIFY2(message.contains("is not the parent of tail"), qPrintable(message));
    QCOMPARE(errorPath(replaced(good, "\"parent_bone\": 1", "\"parent_bone\": \"one\"")),
             QStringLiteral("bones[3].parent_bone"));
    QCOMPARE(errorPath(replaced(good, "\"parent_bone\": 1", "\"parent_bone\": 2")),
             QStringLiteral("bones[3].parent_bone"));
    QCOMPARE(errorPath(replaced(good, "\"trimlab-skeleton\"", "\"something-else\"")), QStringLiteral("format"));
    QCOMPARE(errorPath(replaced(good, "\"version\": 1", "\"version\": 2"), &message), QStringLiteral("version"));
    QVERIFY(message.contains("newer"));
    QCOMPARE(errorPath(replaced(good, "\"root\": 0", "\"root\": 0, \"roots\": 1")), QStringLiteral("roots"));
    QCOMPARE(errorPath(replaced(good, "\"root\": 0", "\"root\": 9")), QStringLiteral("root"));
    // Edges must repeat the bones; vertex_joint must name joints.
    QCOMPARE(errorPath(replaced(good, "\"edges\": [\n  [\n   0,\n   1", "\"edges\": [\n  [\n   0,\n   3")),
             QStringLiteral("edges[0]"));
    QCOMPARE(errorPath(replaced(good, "\"vertex_joint\": []", "\"vertex_joint\": [0, 1, 5]")),
             QStringLiteral("vertex_joint[2]"));
    QCOMPARE(errorPath(replaced(good, "\"vertex_joint\": []", "\"vertex_joint\": [0, -1]")),
             QStringLiteral("vertex_joint[1]"));
    QCOMPARE(errorPath(replaced(good, "\"vertex_joint\": []",
                                "\"vertex_joint\": [], \"curve_skeleton\": {\"nodes\": [[0,0,0]], \"edges\": [[0, 1]], "
                                "\"vertex_node\": []}")),
             QStringLiteral("curve_skeleton.edges[0]"));
    QCOMPARE(errorPath(replaced(good, "\"vertex_joint\": []", "\"vertex_joint\": [], \"curve_skeleton\": 3")),
             QStringLiteral("curve_skeleton"));
    QVERIFY_THROWS_EXCEPTION(SkeletonFileError, (void)loadSkeletonJson(m_dir.filePath("missing.json").toStdString()));
}

void TestSkeletonExport::rigValidationNamesTheField()
{
    SkeletonRig rig = m_rig;
    rig.bones[3].parentBone = -1;
    std::optional<RigProblem> problem = findRigProblem(rig);
    QVERIFY(problem);
    QCOMPARE(QString::fromStdString(problem->where), QStringLiteral("bones[3].parent_bone"));
    rig = m_rig;
    std::swap(rig.bones[1], rig.bones[3]); // the child before its parent
    rig.bones[1].parentBone = 3;
    problem = findRigProblem(rig);
    QVERIFY(problem);
    QCOMPARE(QString::fromStdString(problem->where), QStringLiteral("bones[1].parent_bone"));
    QVERIFY(problem->reason.find("parents first") != std::string::npos);
    rig = m_rig;
    rig.parent = {-1, 0, 4, 0, 2}; // 2 → 4 → 2
    rig.bones[1] = {2, 4, 3};
    problem = findRigProblem(rig);
    QVERIFY(problem);
    QVERIFY2(problem->reason.find("cycle") != std::string::npos, problem->reason.c_str());
    rig = m_rig;
    rig.vertexJoint = {0, 1};
    QVERIFY(findRigProblem(rig, 2) == std::nullopt);
    QCOMPARE(QString::fromStdString(findRigProblem(rig, 3)->where), QStringLiteral("vertex_joint"));
}

QTEST_GUILESS_MAIN(TestSkeletonExport)
#include "tst_skeleton_export.moc"
