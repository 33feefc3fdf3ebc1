// The graph steps of skeleton extraction on small hand-made inputs: the collapse complex of
// the simplification, vertex adjacency and cheapest paths, the selection of joints, the rig
// hierarchy built from them, and the stage views' vertex colours.
#include "core/skeleton/body_root.h"
#include "core/skeleton/bone_names.h"
#include "core/skeleton/collapse_complex.h"
#include "core/skeleton/mesh_adjacency.h"
#include "core/skeleton/rig_hierarchy.h"
#include "core/skeleton/rig_measures.h"
#include "core/skeleton/skeleton_selection.h"
#include "core/skeleton/skeleton_stage_colors.h"

#include "core/animation/color_wheel.h"
#include "core/image/heat_map_colors.h"
#include "core/image/packed_rgba8.h"

#include <QtTest>

#include <cmath>
#include <set>
#include <limits>
#include <stdexcept>

using namespace trimlab;

namespace {

// A tetrahedron: 4 vertices, 6 edges, 4 faces.
const std::vector<glm::dvec3> kTetraPositions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const std::vector<glm::uvec3> kTetraFaces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

// A curve of `nodes` joined in a chain 0–1–2–…, each node absorbing the one vertex at its
// own position (returned in `vertices`).
CurveSkeleton chainCurve(const std::vector<glm::dvec3>& nodes, std::vector<glm::dvec3>& vertices)
{
    CurveSkeleton curve;
    curve.nodes = nodes;
    for (std::size_t k = 0; k + 1 < nodes.size(); ++k)
        curve.edges.push_back({int(k), int(k) + 1});
    vertices = nodes;
    for (std::size_t k = 0; k < nodes.size(); ++k)
        curve.vertexNode.push_back(int(k));
    return curve;
}

// Every node of `curve` a joint, the edges as they are.
NodeSelection everyNode(const CurveSkeleton& curve)
{
    NodeSelection selection;
    for (std::size_t k = 0; k < curve.nodes.size(); ++k) {
        selection.survivors.push_back(int(k));
        selection.jointOfNode.push_back(int(k));
    }
    selection.edges = curve.edges;
    return selection;
}

// Appends to `curve` a polyline from node `from` to `to` in steps of about `step`, each
// new node absorbing `mass` vertices at its position (appended to `vertices`); returns
// the last node.
int appendLimb(CurveSkeleton& curve, std::vector<glm::dvec3>& vertices, int from, const glm::dvec3& to, double step,
               int mass)
{
    const glm::dvec3 start = curve.nodes[std::size_t(from)];
    const int steps = std::max(1, int(std::lround(glm::length(to - start) / step)));
    int previous = from;
    for (int i = 1; i <= steps; ++i) {
        const int node = int(curve.nodes.size());
        curve.nodes.push_back(start + (to - start) * (double(i) / steps));
        curve.edges.push_back({previous, node});
        for (int m = 0; m < mass; ++m) {
            vertices.push_back(curve.nodes.back());
            curve.vertexNode.push_back(node);
        }
        previous = node;
    }
    return previous;
}

// A stick figure's curve skeleton: a spine from the pelvis (node 0, at the origin) to
// the chest, legs from the pelvis, arms and a bulky head from the chest, and three short
// fingers at each hand.
struct StickFigure {
    CurveSkeleton curve;
    std::vector<glm::dvec3> vertices;
    std::vector<int> feet, hands;

    StickFigure()
    {
        curve.nodes = {{0, 0, 0}};
        vertices = {{0, 0, 0}};
        curve.vertexNode = {0};
        const int chest = appendLimb(curve, vertices, 0, {0, 3, 0}, 0.25, 4);
        for (const double side : {-1.0, 1.0}) {
            feet.push_back(appendLimb(curve, vertices, 0, {side * 0.6, -2.0, 0.2}, 0.25, 2));
            feet.back() = appendLimb(curve, vertices, feet.back(), {side * 1.0, -4.0, 0.0}, 0.25, 2);
            const int hand = appendLimb(curve, vertices, chest, {side * 3.0, 2.0, 0}, 0.25, 2);
            hands.push_back(hand);
            for (const double spread : {-0.1, 0.0, 0.1})
                appendLimb(curve, vertices, hand, {side * 3.3, 2.0 + spread, 0}, 0.1, 1);
        }
        appendLimb(curve, vertices, chest, {0, 4.5, 0}, 0.25, 6);
    }
};

// The joints from `joint` up to the root, `joint` first.
std::vector<int> pathToRoot(const SkeletonRig& rig, int joint)
{
    std::vector<int> path{joint};
    while (rig.parent[std::size_t(path.back())] >= 0)
        path.push_back(rig.parent[std::size_t(path.back())]);
    return path;
}

} // namespace

class TestSkeletonGraph : public QObject {
    Q_OBJECT

private slots:
    // A tetrahedron collapsed edge by edge: triangles holding both ends of a collapsed edge
    // die, the others move to the survivor, and once none is left the last edge stays as a
    // skeleton edge. An unused vertex stays isolated and alive.
    void collapsesTurnATetrahedronIntoAnEdge()
    {
        std::vector<glm::dvec3> positions = kTetraPositions;
        positions.emplace_back(5, 5, 5); // used by no triangle
        CollapseComplex complex(positions, kTetraFaces);
        QCOMPARE(complex.vertexCount(), std::size_t(5));
        QCOMPARE(complex.liveTriangleCount(), std::size_t(4));
        QCOMPARE(complex.neighbours(0), (std::vector<int>{1, 2, 3}));
        QVERIFY(complex.neighbours(4).empty());
        QVERIFY(complex.edgeHasTriangle(0, 1));

        complex.collapse(3, 0); // faces (0,1,3) and (0,3,2) die; (1,2,3) becomes (1,2,0)
        QVERIFY(!complex.alive(3));
        QCOMPARE(complex.liveTriangleCount(), std::size_t(2));
        QCOMPARE(complex.liveVertexCount(), std::size_t(4));
        QCOMPARE(complex.representative(3), 0);
        QCOMPARE(complex.position(0), kTetraPositions[0]);
        std::vector<int> around = complex.neighbours(0);
        std::sort(around.begin(), around.end());
        QCOMPARE(around, (std::vector<int>{1, 2}));
        QCOMPARE(complex.neighbours(1).size(), std::size_t(2)); // 0 and 2, never 3

        complex.collapse(2, 1); // both remaining faces hold 1 and 2
        QCOMPARE(complex.liveTriangleCount(), std::size_t(0));
        QCOMPARE(complex.neighbours(0), (std::vector<int>{1}));
        QVERIFY(!complex.edgeHasTriangle(0, 1));

        complex.collapse(1, 0);
        QCOMPARE(complex.representative(2), 0); // through 1
        QCOMPARE(complex.representative(3), 0);
        QCOMPARE(complex.liveVertexCount(), std::size_t(2)); // 0 and the isolated 4
        QVERIFY(complex.alive(4));
        QVERIFY(complex.neighbours(0).empty());
    }

    void adjacencyListsEdgesWithTheirLengths()
    {
        TriangleMesh mesh;
        mesh.positions = {{0, 0, 0}, {3, 0, 0}, {3, 4, 0}, {0, 4, 0}};
        mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
        const VertexAdjacency adjacency = vertexAdjacency(mesh);
        QCOMPARE(adjacency.size(), std::size_t(4));
        bool sawDiagonal = false;
        for (const auto& [to, length] : adjacency[0]) {
            QVERIFY(to == 1 || to == 2 || to == 3);
            const double expected = to == 1 ? 3.0 : to == 3 ? 4.0 : 5.0;
            QCOMPARE(length, expected);
            sawDiagonal = sawDiagonal || to == 2;
        }
        QVERIFY(sawDiagonal);
        for (const auto& [to, length] : adjacency[1]) // never joined to 3
            QVERIFY(to != 3 && length > 0.0);
    }

    // A path 0–1–2–3 of unit steps and a shortcut 0–3 costing 5: the walk wins. The ends'
    // costs count: starting at 1 (cost 0.5) beats starting at 0 (cost 0).
    void cheapestPathCountsStepsAndEndCosts()
    {
        VertexAdjacency graph(5);
        const auto join = [&](std::uint32_t a, std::uint32_t b, double cost) {
            graph[a].push_back({b, cost});
            graph[b].push_back({a, cost});
        };
        join(0, 1, 1.0);
        join(1, 2, 1.0);
        join(2, 3, 1.0);
        join(0, 3, 5.0);
        QCOMPARE(cheapestPath(graph, {{0, 0.0}}, {{3, 0.0}}), (std::vector<std::uint32_t>{0, 1, 2, 3}));
        QCOMPARE(cheapestPath(graph, {{0, 0.0}, {1, 0.5}}, {{3, 0.0}}), (std::vector<std::uint32_t>{1, 2, 3}));
        QCOMPARE(cheapestPath(graph, {{0, 0.0}}, {{3, 0.0}, {2, 10.0}}), (std::vector<std::uint32_t>{0, 1, 2, 3}));
        QVERIFY(cheapestPath(graph, {{0, 0.0}}, {{4, 0.0}}).empty()); // 4 is joined to nothing
    }

    // The ends of a chain stay; the longest segment gains the next joint, in its middle
    // half (all nodes are equally wide here: the first of them). A node between joints
    // joins the nearer one.
    void selectionSplitsTheLongestSegmentsFirst()
    {
        std::vector<glm::dvec3> vertices;
        const CurveSkeleton curve = chainCurve({{0, 0, 0}, {1, 0, 0}, {1.1, 0, 0}, {2, 0, 0}, {3, 0, 0}}, vertices);
        const NodeSelection four = selectSkeletonNodes(curve, vertices, 4);
        QCOMPARE(four.survivors, (std::vector<int>{0, 1, 3, 4}));
        QCOMPARE(four.jointOfNode, (std::vector<int>{0, 1, 1, 2, 3}));
        QCOMPARE(four.edges, (std::vector<std::array<int, 2>>{{0, 1}, {1, 2}, {2, 3}}));
        const NodeSelection again = selectSkeletonNodes(curve, vertices, 4);
        QCOMPARE(again.survivors, four.survivors);
        QCOMPARE(again.jointOfNode, four.jointOfNode);

        std::vector<glm::dvec3> tipVertices;
        const CurveSkeleton tip = chainCurve({{0, 0, 0}, {0.1, 0, 0}, {1, 0, 0}, {2, 0, 0}}, tipVertices);
        const NodeSelection three = selectSkeletonNodes(tip, tipVertices, 3);
        QCOMPARE(three.survivors, (std::vector<int>{0, 2, 3}));
        QCOMPARE(three.jointOfNode[1], 0);

        QCOMPARE(selectSkeletonNodes(curve, vertices, 10).survivors.size(), std::size_t(5));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)selectSkeletonNodes(curve, vertices, 0));
        vertices.pop_back();
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)selectSkeletonNodes(curve, vertices, 3));
    }

    // The joints go where the body is: fingers shorter than the joint spacing merge into
    // their hand, the root is the pelvis (the heavier pair of limbs), every leg is a chain
    // of at least three joints below it, and the count is within 20 % of the target.
    void selectionFollowsTheBody()
    {
        const StickFigure figure;
        for (const int target : {16, 20, 30}) {
            const NodeSelection selection = selectSkeletonNodes(figure.curve, figure.vertices, target);
            const SkeletonRig rig = buildSkeletonRig(figure.curve, selection, figure.vertices, -1);
            const auto count = double(rig.joints.size());
            QVERIFY2(count >= 0.8 * target && count <= 1.2 * target, qPrintable(QString::number(count)));
            QCOMPARE(rig.joints[std::size_t(rig.root)], glm::dvec3(0.0));
            const RigMeasures measures = measureRig(
                rig,
                BoneWeights{std::vector<std::array<int, kBoneInfluences>>(rig.vertexJoint.size(), {-1, -1, -1, -1}),
                            std::vector<std::array<float, kBoneInfluences>>(rig.vertexJoint.size(), {0, 0, 0, 0})});
            QCOMPARE(measures.rootBones, 3);
            QCOMPARE(measures.turnBacks, 0);
            for (const glm::dvec3& joint : rig.joints)
                QVERIFY2(std::abs(joint.x) <= 3.0 + 1e-9, "a finger kept a joint");
            for (const int foot : figure.feet) {
                const int joint = selection.jointOfNode[std::size_t(foot)];
                QCOMPARE(rig.joints[std::size_t(joint)], figure.curve.nodes[std::size_t(foot)]);
                QVERIFY(pathToRoot(rig, joint).size() >= 4); // three joints and the pelvis
            }
        }
    }

    // The stick figure's bones are named by body part: the spine, the legs from the
    // pelvis, the arms from the chest, L on the +x side; every name once.
    void bonesAreNamedByBodyPart()
    {
        const StickFigure figure;
        const NodeSelection selection = selectSkeletonNodes(figure.curve, figure.vertices, 20);
        const SkeletonRig rig = buildSkeletonRig(figure.curve, selection, figure.vertices, -1);
        const std::vector<std::string> names = boneNames(rig);
        QCOMPARE(names.size(), rig.bones.size());
        QCOMPARE(std::set<std::string>(names.begin(), names.end()).size(), names.size());
        const auto boneNamed = [&](const std::string& name) {
            const auto it = std::find(names.begin(), names.end(), name);
            return it == names.end() ? -1 : int(it - names.begin());
        };
        for (const char* name :
             {"spine_1", "spine_2", "leg_L_1", "leg_L_3", "leg_R_1", "leg_R_3", "arm_L_1", "arm_R_1"})
            QVERIFY2(boneNamed(name) >= 0, name);
        const auto tailOf = [&](const char* name) {
            return rig.joints[std::size_t(rig.bones[std::size_t(boneNamed(name))].tail)];
        };
        QVERIFY(tailOf("leg_L_1").x > 0.0 && tailOf("leg_R_1").x < 0.0);
        QVERIFY(tailOf("arm_L_1").x > 0.0 && tailOf("arm_R_1").x < 0.0);
        QCOMPARE(rig.bones[std::size_t(boneNamed("leg_L_1"))].head, rig.root);
        QCOMPARE(rig.bones[std::size_t(boneNamed("leg_L_2"))].parentBone, boneNamed("leg_L_1"));
        QVERIFY(boneNames(SkeletonRig{}).empty());
    }

    // The pelvis is where a pair of limbs leaves at the end of the body; without a pair,
    // the hub nearest the centre of mass; without a junction (a snake), the centre.
    void bodyRootIsThePelvisOrTheCentre()
    {
        // 0 — 1 — 2: legs (3, 4) at 0; arms (5, 6) and a head (7) at 2. The hips have the
        // heavier side: the trunk, the arms and the head.
        const std::vector<std::vector<int>> body = {{1, 3, 4}, {0, 2}, {1, 5, 6, 7}, {0}, {0}, {2}, {2}, {2}};
        QCOMPARE(bodyRoot(body, std::vector<std::size_t>{10, 10, 10, 30, 30, 20, 20, 30}), 0);
        // Legs far lighter than each other are no pair: the shoulders.
        QCOMPARE(bodyRoot(body, std::vector<std::size_t>{10, 10, 10, 8, 30, 20, 20, 30}), 2);
        // No pair anywhere: the junction whose largest part is lighter (0: 52 against 61).
        QCOMPARE(bodyRoot(body, std::vector<std::size_t>{10, 10, 10, 1, 40, 1, 30, 1}), 0);
        const std::vector<std::vector<int>> snake = {{1}, {0, 2}, {1, 3}, {2, 4}, {3}};
        QCOMPARE(bodyRoot(snake, std::vector<std::size_t>{1, 1, 1, 1, 1}), 2);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)bodyRoot(snake, std::vector<std::size_t>{1}));
    }

    // A chain whose curve doubles back: the joint at the fold goes, so no bone turns
    // back on its parent.
    void zigZagsAreStraightened()
    {
        std::vector<glm::dvec3> vertices;
        const CurveSkeleton curve = chainCurve({{0, 0, 0},
                                                {1, 0, 0},
                                                {2, 0, 0},
                                                {3, 0, 0},
                                                {2.2, 0.2, 0},
                                                {3.2, 0.4, 0},
                                                {4.2, 0.4, 0},
                                                {5.2, 0.4, 0},
                                                {6.2, 0.4, 0}},
                                               vertices);
        const NodeSelection selection = selectSkeletonNodes(curve, vertices, 9);
        const SkeletonRig rig = buildSkeletonRig(curve, selection, vertices, -1);
        const BoneWeights none{std::vector<std::array<int, kBoneInfluences>>(vertices.size(), {-1, -1, -1, -1}),
                               std::vector<std::array<float, kBoneInfluences>>(vertices.size(), {0, 0, 0, 0})};
        QCOMPARE(measureRig(rig, none).turnBacks, 0);
        QVERIFY(rig.joints.size() < curve.nodes.size());
        // Every joint everywhere: the fold turns back twice.
        QCOMPARE(measureRig(buildSkeletonRig(curve, everyNode(curve), vertices, 0), none).turnBacks, 2);
    }

    // The rig's measures on a hand-made chain: bones at the root, a bone that turns back,
    // and weight given to a bone two joints away from the vertex's own joint.
    void rigMeasuresCountTurnBacksAndLeakage()
    {
        SkeletonRig rig;
        rig.joints = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}, {2.5, 0.1, 0}};
        rig.parent = {-1, 0, 1, 2, 3, 4};
        rig.root = 0;
        rig.bones = {{0, 1, -1}, {1, 2, 0}, {2, 3, 1}, {3, 4, 2}, {4, 5, 3}};
        rig.vertexJoint = {0, 0};
        BoneWeights weights;
        weights.bones = {{0, -1, -1, -1}, {0, 3, -1, -1}};
        weights.weights = {{1.0f, 0, 0, 0}, {0.5f, 0.5f, 0, 0}};
        const RigMeasures m = measureRig(rig, weights);
        QCOMPARE(m.joints, 6);
        QCOMPARE(m.rootBones, 1);
        QCOMPARE(m.turnBacks, 1);
        QVERIFY(m.sharpestTurnDegrees > 170.0 && m.sharpestTurnDegrees < 180.0);
        QCOMPARE(m.leakedWeight, 0.25);
        QCOMPARE(m.leakingVertices, 0.5);
        QVERIFY(describeRigMeasures(m).find("1 turn-backs beyond 120") != std::string::npos);
        weights.bones[1][1] = 7;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)measureRig(rig, weights));
        rig.vertexJoint.push_back(0);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)measureRig(rig, weights));
    }

    // A T: the junction (degree 3) becomes the root, bones leave it breadth-first with
    // their parents first, and each vertex takes the joint of its node's region.
    void rigOfATRootsAtTheJunction()
    {
        CurveSkeleton curve;
        curve.nodes = {{-1, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, -2, 0}};
        curve.edges = {{0, 1}, {1, 2}, {1, 3}, {3, 4}};
        curve.vertexNode = {0, 1, 2, 3, 4, 4};
        const std::vector<glm::dvec3> vertices = {{-1, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, -2, 0}, {0, -2, 0}};
        const SkeletonRig rig = buildSkeletonRig(curve, everyNode(curve), vertices, -1);
        QCOMPARE(rig.root, 1);
        QCOMPARE(rig.joints, curve.nodes);
        QCOMPARE(rig.parent, (std::vector<int>{1, -1, 1, 1, 3}));
        QCOMPARE(rig.bones.size(), std::size_t(4));
        // Breadth-first from the root, neighbours in index order: tails 0, 2, 3, then 4.
        const std::vector<int> tails = {rig.bones[0].tail, rig.bones[1].tail, rig.bones[2].tail, rig.bones[3].tail};
        QCOMPARE(tails, (std::vector<int>{0, 2, 3, 4}));
        QCOMPARE(rig.bones[3].head, 3);
        QCOMPARE(rig.bones[3].parentBone, 2);
        QCOMPARE(rig.bones[0].parentBone, -1);
        QCOMPARE(rig.vertexJoint, (std::vector<int>{0, 1, 2, 3, 4, 4}));

        const SkeletonRig rooted = buildSkeletonRig(curve, everyNode(curve), vertices, 4);
        QCOMPARE(rooted.root, 4);
        QCOMPARE(rooted.parent[4], -1);
        QCOMPARE(rooted.parent[3], 4);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)buildSkeletonRig(curve, everyNode(curve), vertices, 5));
    }

    // A loop (the curve of a torus) opens into a tree: one edge is dropped. Another
    // component is attached at its nearest joint. No joints: an empty rig.
    void rigOpensLoopsAndJoinsComponents()
    {
        CurveSkeleton loop;
        loop.nodes = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {3, 0, 0}};
        loop.edges = {{0, 1}, {1, 2}, {2, 3}, {0, 3}};
        loop.vertexNode = {0, 1, 2, 3, 4};
        const SkeletonRig rig = buildSkeletonRig(loop, everyNode(loop), loop.nodes, 0);
        QCOMPARE(rig.bones.size(), std::size_t(4));
        QCOMPARE(rig.parent[0], -1);
        QCOMPARE(rig.parent[1], 0);
        QCOMPARE(rig.parent[3], 0);
        QVERIFY(rig.parent[2] == 1 || rig.parent[2] == 3);
        QCOMPARE(rig.parent[4], 0); // the lone node, nearest to joint 0

        const SkeletonRig empty = buildSkeletonRig(loop, NodeSelection{}, loop.nodes, -1);
        QVERIFY(empty.joints.empty() && empty.bones.empty());
        QCOMPARE(empty.root, 0);
        QCOMPARE(empty.vertexJoint, std::vector<int>(5, -1));
    }

    void laplacianColorsScaleToTheLargestFiniteValue()
    {
        const std::vector<double> magnitude = {0.0, 2.0, std::nan(""), std::numeric_limits<double>::infinity(), 1.0};
        double largest = -1.0;
        const std::vector<std::uint32_t> colors = laplacianColors(magnitude, largest);
        QCOMPARE(largest, 2.0);
        const std::vector<std::uint32_t> expected = heatMapRgba8(std::vector<double>{0.0, 2.0, 0.0, 0.0, 1.0}, 2.0);
        QCOMPARE(colors, expected);
        QVERIFY(colors[0] != colors[1] && colors[4] != colors[1]);

        const std::vector<std::uint32_t> flat = laplacianColors(std::vector<double>{0.0, 0.0}, largest);
        QCOMPARE(largest, 0.0);
        QCOMPARE(flat[0], flat[1]);
    }

    // Neighbouring nodes differ in colour, so a chain alternates; vertices of no valid node
    // are grey; joints take their own palette colours.
    void regionColorsTellNeighboursApart()
    {
        const std::uint32_t grey = packRgba8(glm::vec3(0.6f));
        CurveSkeleton curve;
        curve.nodes = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 1, 0}};
        curve.edges = {{0, 1}, {1, 2}, {1, 3}};
        curve.vertexNode = {0, 1, 2, 3, -1, 9};
        const std::vector<std::uint32_t> nodes = curveMappingColors(curve);
        QCOMPARE(nodes.size(), std::size_t(6));
        QVERIFY(nodes[0] != nodes[1] && nodes[2] != nodes[1] && nodes[3] != nodes[1]);
        QCOMPARE(nodes[0], nodes[2]);
        QCOMPARE(nodes[4], grey);
        QCOMPARE(nodes[5], grey);

        SkeletonRig rig;
        rig.joints = {{0, 0, 0}, {1, 0, 0}};
        rig.vertexJoint = {1, 0, -1, 2};
        const std::vector<std::uint32_t> joints = jointSegmentColors(rig);
        QCOMPARE(joints[0], packRgba8(paletteColor(1).rgb()));
        QCOMPARE(joints[1], packRgba8(paletteColor(0).rgb()));
        QCOMPARE(joints[2], grey);
        QCOMPARE(joints[3], grey);
    }

    void boneWeightColorsClampToTheUnitRange()
    {
        const std::vector<std::uint32_t> colors =
            boneWeightColors(std::vector<double>{-1.0, 0.0, 0.5, 1.0, 2.0, std::nan("")});
        QCOMPARE(colors, heatMapRgba8(std::vector<double>{0.0, 0.0, 0.5, 1.0, 1.0, 0.0}, 1.0));
        QVERIFY(colors[2] != colors[1] && colors[2] != colors[3]);
    }
};

QTEST_APPLESS_MAIN(TestSkeletonGraph)
#include "tst_skeleton_graph.moc"
