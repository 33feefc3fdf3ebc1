// Bone-heat weights (Berenguer & Moreno III.E; Baran & Popović 2007): the Meyer Laplacian,
// the heat terms (nearest bones, ties, visibility) and the solved weights on generated
// closed meshes with hand-built rigs.
#include "core/skeleton/bone_heat_terms.h"
#include "core/skeleton/bone_heat_weights.h"
#include "core/skeleton/meyer_laplacian.h"

#include "core/mesh/mesh_validation.h"
#include "core/scene/shape_generators.h"

#include "skeleton_rig_fixtures.h"
#include "skeleton_shapes.h"

#include <QtTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

using namespace trimlab;

namespace {

// Checks the BoneWeights invariants for every vertex; returns "" or the first problem.
QString convexityProblem(const BoneWeights& w, std::size_t boneCount)
{
    for (std::size_t v = 0; v < w.vertexCount(); ++v) {
        double sum = 0.0;
        for (std::size_t k = 0; k < kBoneInfluences; ++k) {
            const int b = w.bones[v][k];
            const float x = w.weights[v][k];
            if (!std::isfinite(x) || x < 0.0f)
                return QString("vertex %1 slot %2: weight %3").arg(v).arg(k).arg(x);
            if (b < 0 ? x != 0.0f : (b >= int(boneCount) || x == 0.0f))
                return QString("vertex %1 slot %2: bone %3 with weight %4").arg(v).arg(k).arg(b).arg(x);
            if (k > 0 && x > w.weights[v][k - 1])
                return QString("vertex %1: weights not sorted").arg(v);
            sum += x;
        }
        if (std::abs(sum - 1.0) > 1e-6)
            return QString("vertex %1: weights sum to %2").arg(v).arg(sum, 0, 'g', 10);
    }
    return {};
}

int dominantBone(const BoneWeights& w, std::size_t v)
{
    return w.bones[v][0];
}

float weightOf(const BoneWeights& w, std::size_t v, int bone)
{
    for (std::size_t k = 0; k < kBoneInfluences; ++k)
        if (w.bones[v][k] == bone)
            return w.weights[v][k];
    return 0.0f;
}

double surfaceArea(const TriangleMesh& mesh)
{
    double area = 0.0;
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
        area += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    return area;
}

std::vector<glm::dvec3> doublePositions(const TriangleMesh& mesh)
{
    return {mesh.positions.begin(), mesh.positions.end()};
}

// An octahedron |x|/2 + |y|/2 + |z| ≤ 1 with its top vertex at (0, 0, 1).
TriangleMesh octahedron()
{
    TriangleMesh m;
    m.positions = {{2, 0, 0}, {0, 2, 0}, {-2, 0, 0}, {0, -2, 0}, {0, 0, 1}, {0, 0, -1}};
    for (unsigned i = 0; i < 4; ++i) {
        m.triangles.emplace_back(i, (i + 1) % 4, 4u);
        m.triangles.emplace_back((i + 1) % 4, i, 5u);
    }
    return m;
}

// An arm hanging beside a body with a gap between them, joined at the shoulder: the
// body x, z ∈ [−1, 1], y ∈ [−3, 3]; the arm x ∈ [1.25, 1.75], z ∈ [−0.25, 0.25],
// y ∈ [−2.5, 2.5]; the shoulder x ∈ [1, 1.25], y ∈ [2, 2.5], z ∈ [−0.25, 0.25]. The
// body's side facing the arm is nearer to the arm's bone (0.5) than to the spine (1), so
// only visibility keeps the arm's weight off it.
bool insideArmBeside(const glm::dvec3& p)
{
    const bool body = std::abs(p.x) < 1 && std::abs(p.z) < 1 && std::abs(p.y) < 3;
    const bool arm = p.x > 1.25 && p.x < 1.75 && std::abs(p.z) < 0.25 && std::abs(p.y) < 2.5;
    const bool shoulder = p.x >= 1 && p.x <= 1.25 && p.y > 2 && p.y < 2.5 && std::abs(p.z) < 0.25;
    return body || arm || shoulder;
}

TriangleMesh armBesideBody()
{
    constexpr double cell = 0.25;
    std::vector<std::array<int, 3>> cells;
    for (int x = -4; x < 7; ++x)
        for (int y = -12; y < 12; ++y)
            for (int z = -4; z < 4; ++z)
                if (insideArmBeside(glm::dvec3(x + 0.5, y + 0.5, z + 0.5) * cell))
                    cells.push_back({x, y, z});
    return test::voxelSurface(cells, cell);
}

// Spine from the pelvis to the neck, a collar bone out to the shoulder, the arm down.
SkeletonRig armBesideBodyRig()
{
    SkeletonRig rig;
    rig.joints = {{0.0, -2.5, 0.0}, {0.0, 2.25, 0.0}, {1.5, 2.25, 0.0}, {1.5, -2.25, 0.0}};
    rig.parent = {-1, 0, 1, 2};
    rig.root = 0;
    rig.bones = {{0, 1, -1}, {1, 2, 0}, {2, 3, 1}};
    return rig;
}

} // namespace

class TestSkeletonWeights : public QObject {
    Q_OBJECT
private slots:
    void laplacianAreasSumToSurfaceArea();
    void laplacianIsZeroOnLinearFunctionsOfAPlane();
    void laplacianSurvivesDegenerateTriangles();
    void segmentVisibilityOnTheT();
    void segmentVisibilityThroughASelfIntersection();
    void equidistantBonesSplitTheSource();
    void tiedNearestPointAtAJoint();
    void capsuleWeightsAreConvexAndFollowTheChain();
    void tLimbsAreDominatedByTheirBones();
    void armWeightsDoNotCrossTheGapToTheBody();
    void componentWithoutHeatFallsBackToNearestBone();
    void orderingsAndBackendsAgree();
    void badRigsAreRefused();
};

void TestSkeletonWeights::laplacianAreasSumToSurfaceArea()
{
    const TriangleMesh capsule = test::axisCapsule(1.0, 3.0, 6, 12, 24);
    const MeyerLaplacian l = meyerLaplacian(doublePositions(capsule), capsule.triangles);
    double total = 0.0;
    for (const double a : l.area) {
        QVERIFY(a > 0.0);
        total += a;
    }
    QVERIFY(std::abs(total - surfaceArea(capsule)) < 1e-9 * total);
    QCOMPARE(l.skippedTriangles, std::size_t(0));
    // Row sums of the stiffness matrix are 0 (constants are harmonic).
    std::vector<double> rows = l.diagonal;
    for (const LaplacianEdge& e : l.edges) {
        QVERIFY(e.i < e.j);
        rows[e.i] -= e.weight;
        rows[e.j] -= e.weight;
    }
    for (const double r : rows)
        QVERIFY(std::abs(r) < 1e-9);
}

void TestSkeletonWeights::laplacianIsZeroOnLinearFunctionsOfAPlane()
{
    // A jittered planar grid: the cotangent Laplacian of a linear function vanishes at
    // every interior vertex, also next to obtuse triangles.
    TriangleMesh grid;
    const int n = 8;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) {
            const bool interior = x > 0 && y > 0 && x < n && y < n;
            const float jx = interior ? 0.3f * float(std::sin(x * 7.1 + y * 3.3)) : 0.0f;
            const float jy = interior ? 0.3f * float(std::cos(x * 2.9 + y * 5.7)) : 0.0f;
            grid.positions.emplace_back(float(x) + jx, float(y) + jy, 0.0f);
        }
    for (unsigned y = 0; y < unsigned(n); ++y)
        for (unsigned x = 0; x < unsigned(n); ++x) {
            const unsigned a = y * (n + 1) + x;
            grid.triangles.emplace_back(a, a + 1, a + n + 2);
            grid.triangles.emplace_back(a, a + n + 2, a + n + 1);
        }
    const std::vector<glm::dvec3> p = doublePositions(grid);
    const MeyerLaplacian l = meyerLaplacian(p, grid.triangles);
    auto f = [](const glm::dvec3& q) { return 2.0 * q.x - 3.0 * q.y + 0.5; };
    std::vector<double> lf(p.size());
    for (std::size_t i = 0; i < p.size(); ++i)
        lf[i] = l.diagonal[i] * f(p[i]);
    for (const LaplacianEdge& e : l.edges) {
        lf[e.i] -= e.weight * f(p[e.j]);
        lf[e.j] -= e.weight * f(p[e.i]);
    }
    for (int y = 1; y < n; ++y)
        for (int x = 1; x < n; ++x)
            QVERIFY2(std::abs(lf[std::size_t(y * (n + 1) + x)]) < 1e-9,
                     qPrintable(QString::number(lf[std::size_t(y * (n + 1) + x)])));
}

void TestSkeletonWeights::laplacianSurvivesDegenerateTriangles()
{
    // A zero-area triangle (three collinear vertices), a sliver and a repeated index.
    const std::vector<glm::dvec3> p = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 1e-13, 0}, {0, 1, 0}};
    const std::vector<glm::uvec3> t = {{0, 1, 2}, {0, 2, 3}, {0, 1, 1}, {0, 1, 4}};
    const MeyerLaplacian l = meyerLaplacian(p, t);
    QCOMPARE(l.skippedTriangles, std::size_t(2));
    QCOMPARE(l.scaledTriangles, std::size_t(1));
    for (const double d : l.diagonal)
        QVERIFY(std::isfinite(d) && std::abs(d) <= 2.0 * kMaxCotangent);
    for (const double a : l.area)
        QVERIFY(std::isfinite(a) && a >= 0.0);
    for (const LaplacianEdge& e : l.edges)
        QVERIFY(std::isfinite(e.weight));
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, (void)meyerLaplacian(p, std::vector<glm::uvec3>{{0, 1, 9}}));
}

void TestSkeletonWeights::segmentVisibilityOnTheT()
{
    const TriangleMesh t = test::makeTTube();
    QVERIFY(validateMesh(t).trimmable());
    const SegmentVisibility visibility(t);
    std::vector<RayHit> hits;
    const glm::dvec3 leftTop(-4.0, 2.0, 1.0), stemSide(1.0, -4.0, 1.0);
    QVERIFY(visibility.inside(leftTop, {-4.0, 1.0, 1.0}, hits));    // down into the left arm
    QVERIFY(!visibility.inside(stemSide, {3.0, 1.0, 1.0}, hits));   // through the air to the right arm
    QVERIFY(!visibility.inside(leftTop, {-4.0, 3.0, 1.0}, hits));   // leaves the surface outward
    QVERIFY(visibility.inside(stemSide, {0.0, 1.0, 1.0}, hits));    // up the stem into the bar
    QVERIFY(!visibility.inside(stemSide, {-3.0, -1.0, 1.0}, hits)); // out of the stem, under the bar
}

void TestSkeletonWeights::segmentVisibilityThroughASelfIntersection()
{
    // One mesh made of two overlapping spheres (a self-intersecting surface): a segment
    // from the big sphere's left side to a point inside the small one crosses the small
    // sphere's surface (w 1 → 2) and then the big one's (w 2 → 1) without ever leaving
    // the volume, so it is inside; one that ends beyond both is not.
    TriangleMesh mesh = makeIcosphere({0.0, 0.0, 0.0}, 2.0, 2);
    appendMesh(mesh, makeIcosphere({1.5, 0.0, 0.0}, 1.0, 2));
    const auto left = std::size_t(std::min_element(mesh.positions.begin(), mesh.positions.end(),
                                                   [](const glm::vec3& a, const glm::vec3& b) { return a.x < b.x; }) -
                                  mesh.positions.begin());
    const glm::dvec3 p(mesh.positions[left]);
    QVERIFY(p.x < -1.9);
    const SegmentVisibility visibility(mesh);
    std::vector<RayHit> hits;
    QVERIFY(visibility.inside(p, {2.2, 0.0, 0.0}, hits));
    QVERIFY(!visibility.inside(p, {2.8, 0.0, 0.0}, hits));
    QVERIFY(visibility.inside(p, {0.0, 0.5, 0.0}, hits));
}

void TestSkeletonWeights::equidistantBonesSplitTheSource()
{
    // Two bones from (−1, 0, 0) to (1, ±0.5, 0), mirror images in y = 0: the top vertex
    // (0, 0, 1) lies in the mirror plane, so it is exactly as far from both.
    const TriangleMesh mesh = octahedron();
    SkeletonRig rig;
    rig.joints = {{-1, 0, 0}, {1, -0.5, 0}, {1, 0.5, 0}};
    rig.parent = {-1, 0, 0};
    rig.bones = {{0, 1, -1}, {0, 2, -1}};
    const BoneHeatTerms terms = boneHeatTerms(mesh, rig);
    const std::size_t top = 4;
    QCOMPARE(terms.nearest(top).size(), std::size_t(2));
    QCOMPARE(terms.visibleCount(top), std::size_t(2));
    QCOMPARE(terms.source(top, 0), 0.5);
    QCOMPARE(terms.source(top, 1), 0.5);
    // d = distance from (0,0,1) to the bone from (−1,0,0) to (1,−0.5,0).
    const glm::dvec3 q = closestPointOnSegment({0, 0, 1}, rig.joints[0], rig.joints[1]);
    const double d = glm::length(glm::dvec3(0, 0, 1) - q);
    QVERIFY(std::abs(terms.heat[top] - 2.0 / (d * d)) < 1e-12 / (d * d));
    // (0, 2, 0) lies on bone 1's side of the mirror plane: bone 1 alone is nearest.
    QCOMPARE(terms.nearest(1).size(), std::size_t(1));
    QCOMPARE(terms.nearest(1)[0], 1);
    QCOMPARE(terms.source(1, 1), 1.0);
    QCOMPARE(terms.source(1, 0), 0.0);
    // With c = 0.22 (the paper's volume-like constant) H scales, p does not.
    BoneHeatTermOptions options;
    options.heatConstant = 0.22;
    const BoneHeatTerms scaled = boneHeatTerms(mesh, rig, options);
    QVERIFY(std::abs(scaled.heat[top] - 0.22 * terms.heat[top]) < 1e-12 * terms.heat[top]);
    QCOMPARE(scaled.source(top, 0), 0.5);
}

void TestSkeletonWeights::tiedNearestPointAtAJoint()
{
    // Two bones leave the joint (0,0,0) at a right angle; a vertex behind the joint sees
    // the joint as the closest point of both.
    TriangleMesh mesh = makeIcosphere({0.5, 0.5, 0.0}, 3.0, 1);
    SkeletonRig rig;
    rig.joints = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
    rig.parent = {-1, 0, 0};
    rig.bones = {{0, 1, -1}, {0, 2, -1}};
    mesh.positions.push_back({-1.0f, -1.0f, 0.0f}); // an isolated vertex behind the joint
    const BoneHeatTerms terms = boneHeatTerms(mesh, rig);
    const std::size_t v = mesh.vertexCount() - 1;
    QCOMPARE(terms.nearest(v).size(), std::size_t(2));
    // The isolated vertex is inside the sphere; both segments to the joint are inside.
    QCOMPARE(terms.source(v, 0), 0.5);
    QCOMPARE(terms.source(v, 1), 0.5);
}

void TestSkeletonWeights::capsuleWeightsAreConvexAndFollowTheChain()
{
    const TriangleMesh capsule = test::axisCapsule(1.0, 4.0, 8, 32, 32);
    const SkeletonRig rig = test::chainRig({-4.5, -1.5, 1.5, 4.5});
    const BoneHeatSolver solver(capsule, rig);
    const BoneWeights& w = solver.weights();
    QCOMPARE(w.vertexCount(), capsule.vertexCount());
    const QString problem = convexityProblem(w, rig.bones.size());
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    QCOMPARE(solver.report().hiddenVertices, std::size_t(0)); // a convex mesh sees every bone
    QCOMPARE(solver.report().pinnedVertices, std::size_t(0));
    // The poles (y = ∓5) belong to the end bones, almost rigidly.
    const auto byHeight = [](const glm::vec3& a, const glm::vec3& b) { return a.y < b.y; };
    const auto south = std::size_t(std::min_element(capsule.positions.begin(), capsule.positions.end(), byHeight) -
                                   capsule.positions.begin());
    const auto north = std::size_t(std::max_element(capsule.positions.begin(), capsule.positions.end(), byHeight) -
                                   capsule.positions.begin());
    QCOMPARE(dominantBone(w, south), 0);
    QVERIFY(w.weights[south][0] > 0.95f);
    QCOMPARE(dominantBone(w, north), 2);
    QVERIFY(w.weights[north][0] > 0.95f);
    // Along the body the dominant bone is the one at the vertex's height, away from the
    // joints (|y ∓ 1.5| > 0.5), and the raw columns sum to 1 (partition of unity).
    std::vector<std::vector<double>> columns;
    for (int b = 0; b < 3; ++b)
        columns.push_back(solver.boneWeightColumn(b));
    for (std::size_t v = 0; v < capsule.vertexCount(); ++v) {
        const double y = capsule.positions[v].y;
        QVERIFY(std::abs(columns[0][v] + columns[1][v] + columns[2][v] - 1.0) < 1e-8);
        if (std::abs(std::abs(y) - 1.5) < 0.5)
            continue;
        const int expected = y < -1.5 ? 0 : (y < 1.5 ? 1 : 2);
        QVERIFY2(dominantBone(w, v) == expected, qPrintable(QString("vertex %1 at y = %2").arg(v).arg(y)));
    }
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, (void)solver.boneWeightColumn(3));
}

void TestSkeletonWeights::tLimbsAreDominatedByTheirBones()
{
    const TriangleMesh t = test::makeTTube();
    const SkeletonRig rig = test::tRig();
    const BoneHeatSolver solver(t, rig);
    const BoneWeights& w = solver.weights();
    const QString problem = convexityProblem(w, rig.bones.size());
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    std::size_t checkedEnds = 0;
    for (std::size_t v = 0; v < t.vertexCount(); ++v) {
        const glm::dvec3 p(t.positions[v]);
        // The largest weight belongs to a bone whose closest point the vertex sees: the
        // segment stays inside the T (exact box test, 64 samples off the ends).
        const int b = dominantBone(w, v);
        const glm::dvec3 q = closestPointOnSegment(p, rig.joints[std::size_t(rig.bones[std::size_t(b)].head)],
                                                   rig.joints[std::size_t(rig.bones[std::size_t(b)].tail)]);
        for (int s = 1; s < 64; ++s)
            QVERIFY2(test::insideT(p + (q - p) * (s / 64.0)),
                     qPrintable(QString("vertex %1 (%2, %3, %4): bone %5 is not visible")
                                    .arg(v)
                                    .arg(p.x)
                                    .arg(p.y)
                                    .arg(p.z)
                                    .arg(b)));
        // Limbs, away from the junction: the limb's bone dominates; at the far ends it is
        // nearly rigid.
        const int limb = p.x < -3.0 ? 0 : p.x > 3.0 ? 1 : p.y < -3.0 ? 2 : -1;
        if (limb < 0)
            continue;
        QVERIFY2(b == limb, qPrintable(QString("vertex %1 at (%2, %3): bone %4").arg(v).arg(p.x).arg(p.y).arg(b)));
        if (std::abs(p.x) >= 5.5 || p.y <= -5.5) {
            QVERIFY2(weightOf(w, v, limb) > 0.95f, qPrintable(QString::number(weightOf(w, v, limb))));
            ++checkedEnds;
        }
    }
    QVERIFY(checkedEnds > 100);
}

// Weights stay in their limb: the body's side facing the arm, below the shoulder, takes
// next to nothing from the arm's bone, though that bone is its nearest; the arm is the
// arm's own. Bones chosen by distance alone would give that side to the arm.
void TestSkeletonWeights::armWeightsDoNotCrossTheGapToTheBody()
{
    const TriangleMesh mesh = armBesideBody();
    QVERIFY(validateMesh(mesh).trimmable());
    const SkeletonRig rig = armBesideBodyRig();
    QVERIFY(mesh.vertexCount() > 500);
    // The largest arm weight on the body's side facing the arm, away from the shoulder,
    // and the smallest on the arm's lower half.
    const auto armWeights = [&](const BoneWeights& w) {
        float facing = 0.0f, arm = 1.0f;
        for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
            const glm::dvec3 p(mesh.positions[v]);
            if (p.x == 1.0 && p.y < 0.0 && std::abs(p.z) <= 0.5)
                facing = std::max(facing, weightOf(w, v, 2));
            if (p.x >= 1.25 && p.y < 1.0)
                arm = std::min(arm, weightOf(w, v, 2));
        }
        return std::pair{facing, arm};
    };
    const BoneWeights w = boneHeatWeights(mesh, rig);
    const QString problem = convexityProblem(w, rig.bones.size());
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    const auto [worstFacing, weakestArm] = armWeights(w);
    qInfo("largest arm weight on the body's facing side %.4f; smallest on the arm %.4f", double(worstFacing),
          double(weakestArm));
    QVERIFY2(worstFacing < 0.02f, qPrintable(QString::number(worstFacing)));
    QVERIFY2(weakestArm > 0.9f, qPrintable(QString::number(weakestArm)));
    // The same without visibility: the facing side goes to the arm.
    BoneHeatOptions blind;
    blind.terms.visibility = false;
    QVERIFY(armWeights(boneHeatWeights(mesh, rig, blind)).first > 0.5f);
}

void TestSkeletonWeights::componentWithoutHeatFallsBackToNearestBone()
{
    // A capsule and, far to its side, a small sphere: every segment from the sphere to a
    // bone crosses the capsule's surface or leaves the sphere through the air, so the
    // sphere has no heat source; its equations are pinned to the nearest bone.
    TriangleMesh mesh = test::axisCapsule(1.0, 4.0, 6, 16, 24);
    const std::size_t capsuleVertices = mesh.vertexCount();
    appendMesh(mesh, makeIcosphere({6.0, 4.0, 0.0}, 0.5, 1));
    const SkeletonRig rig = test::chainRig({-4.5, 0.0, 4.5});
    const BoneHeatSolver solver(mesh, rig);
    const BoneWeights& w = solver.weights();
    const QString problem = convexityProblem(w, rig.bones.size());
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    QCOMPARE(solver.report().pinnedVertices, mesh.vertexCount() - capsuleVertices);
    QVERIFY(solver.report().hiddenVertices >= mesh.vertexCount() - capsuleVertices);
    for (std::size_t v = capsuleVertices; v < mesh.vertexCount(); ++v) {
        QCOMPARE(w.bones[v][0], 1); // the upper bone (y from 0 to 4.5) is nearest to y ≈ 4
        QCOMPARE(w.weights[v][0], 1.0f);
    }
}

void TestSkeletonWeights::orderingsAndBackendsAgree()
{
    const TriangleMesh t = test::makeTTube();
    const SkeletonRig rig = test::tRig();
    const BoneHeatSolver reference(t, rig);
    QVERIFY(reference.report().factorization.find("METIS") != std::string::npos);
    for (const SparseBackend backend : {SparseBackend::Cholmod, SparseBackend::EigenSimplicialLdlt})
        for (const SparseOrdering ordering : {SparseOrdering::Amd, SparseOrdering::Colamd, SparseOrdering::Metis}) {
            BoneHeatOptions options;
            options.backend = backend;
            options.ordering = ordering;
            const BoneHeatSolver other(t, rig, options);
            QVERIFY(other.report().note.empty());
            // Different elimination orders round differently; the system is well
            // conditioned (diagonal heat terms), so the solutions agree to ~1e-12.
            for (int b = 0; b < 3; ++b) {
                const std::vector<double> x = reference.boneWeightColumn(b), y = other.boneWeightColumn(b);
                for (std::size_t v = 0; v < x.size(); ++v)
                    QVERIFY2(std::abs(x[v] - y[v]) < 1e-9,
                             qPrintable(QString::fromStdString(other.report().factorization)));
            }
        }
}

void TestSkeletonWeights::badRigsAreRefused()
{
    const TriangleMesh capsule = test::axisCapsule(1.0, 2.0, 4, 4, 12);
    SkeletonRig single;
    single.joints = {{0, 0, 0}};
    single.parent = {-1};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)BoneHeatSolver(capsule, single));
    SkeletonRig broken = test::chainRig({-1.0, 1.0});
    broken.bones[0].tail = 7;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)BoneHeatSolver(capsule, broken));
    SkeletonRig nan = test::chainRig({-1.0, 1.0});
    nan.joints[1].x = std::nan("");
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)BoneHeatSolver(capsule, nan));
    BoneHeatOptions cold;
    cold.terms.heatConstant = 0.0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)BoneHeatSolver(capsule, test::chainRig({-1.0, 1.0}), cold));
}

QTEST_GUILESS_MAIN(TestSkeletonWeights)
#include "tst_skeleton_weights.moc"
