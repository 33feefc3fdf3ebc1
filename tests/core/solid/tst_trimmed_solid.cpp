// The trimmed solid exported as exact geometry (core/solid) against the image-space trim
// it must reproduce: closed, consistent windings, every sampled point inside the export
// exactly where the scene's windings and the rule keep it, and the export rendered
// plainly (by the exact CPU reference, positive index) agreeing with the trim of the
// scene from 20 directions.
#include "test_paths.h"
#include "view_directions.h"

#include "core/solid/trimmed_solid.h"
#include "core/solid/exact_profile.h"

#include "core/catalog/demo_scenes.h"
#include "core/catalog/scene_source.h"
#include "core/catalog/demo_shapes.h"
#include "core/scene/object_transform.h"
#include "core/scene/shape_generators.h"
#include "core/trim/clip_polytope.h"
#include "core/trim/csg_expression.h"
#include "core/trim/reference_renderer.h"
#include "core/trim/static_rule.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <QtTest>

#include <numeric>
#include <random>

using namespace trimlab;

namespace {

struct WorldTriangle {
    glm::dvec3 a, b, c;
    int object;
};

std::vector<WorldTriangle> worldTriangles(const Scene& scene)
{
    std::vector<WorldTriangle> out;
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const SceneObject& object = scene.objects[o];
        const auto world = [&](std::uint32_t i) {
            return glm::dvec3(object.modelMatrix * glm::dvec4(glm::dvec3(object.mesh.positions[i]), 1.0));
        };
        for (const glm::uvec3& t : object.mesh.triangles)
            out.push_back({world(t.x), world(t.y), world(t.z), int(o)});
    }
    return out;
}

// Per-object winding numbers of `p` by the signed crossings of a ray in an irregular
// direction (Möller-Trumbore); points this close to a face or edge are rare enough at
// random positions that the test ignores the question.
std::vector<int> windingsAt(const std::vector<WorldTriangle>& triangles, std::size_t objects, const glm::dvec3& p)
{
    const glm::dvec3 dir = glm::normalize(glm::dvec3(0.3183, 0.5772, 0.7531));
    std::vector<int> w(objects, 0);
    for (const WorldTriangle& t : triangles) {
        const glm::dvec3 e1 = t.b - t.a, e2 = t.c - t.a;
        const glm::dvec3 h = glm::cross(dir, e2);
        const double det = glm::dot(e1, h);
        if (std::abs(det) < 1e-300)
            continue;
        const glm::dvec3 s = p - t.a;
        const double u = glm::dot(s, h) / det;
        const glm::dvec3 q = glm::cross(s, e1);
        const double v = glm::dot(dir, q) / det;
        const double along = glm::dot(e2, q) / det;
        if (u < 0.0 || v < 0.0 || u + v > 1.0 || along <= 0.0)
            continue;
        // Leaving through an outward face (dir . n > 0) means p was inside: +1.
        w[std::size_t(t.object)] += glm::dot(dir, glm::cross(e1, e2)) > 0.0 ? 1 : -1;
    }
    return w;
}

bool keptBy(const TrimSettings& settings, const std::vector<int>& w)
{
    if (!settings.csg.enabled())
        return isInterior(settings.rule, std::accumulate(w.begin(), w.end(), 0));
    std::uint32_t bits = 0;
    for (std::size_t o = 0; o < w.size(); ++o)
        bits |= isInterior(settings.objectRule(int(o)), w[o]) ? 1u << o : 0u;
    return evaluateCsg(settings.csg.expression, bits);
}

Scene exportedScene(const TrimmedSolid& solid)
{
    Scene scene;
    scene.objects.push_back({"export", solid.mesh, glm::dmat4(1.0)});
    return scene;
}

// `rule`, and the CSG expression `csg` unless it is empty.
TrimSettings classification(StaticRule rule, const QString& csg)
{
    TrimSettings settings;
    settings.rule = rule;
    if (!csg.isEmpty())
        settings.csg.expression = parseCsgExpression(csg.toStdString(), nullptr).value();
    return settings;
}

constexpr int kSamples = 1500;

// kSamples random points in the scene's box: how many `settings` (and every enabled plane
// of `clips`) keep, at how many the export's winding says otherwise, and at how many it
// is neither 0 nor 1.
struct SampleCheck {
    int kept = 0;
    int mismatches = 0;
    int otherWindings = 0;
};

SampleCheck checkSamples(const Scene& input, const TrimSettings& settings, const TrimmedSolid& solid,
                         const ClipSet& clips, unsigned seed)
{
    const std::vector<WorldTriangle> original = worldTriangles(input);
    const std::vector<WorldTriangle> exported = worldTriangles(exportedScene(solid));
    const Bounds bounds = input.worldBounds();
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    SampleCheck check;
    for (int i = 0; i < kSamples; ++i) {
        const glm::dvec3 p =
            bounds.min + (bounds.max - bounds.min) * glm::dvec3(unit(random), unit(random), unit(random));
        const bool keep = keptBy(settings, windingsAt(original, input.objects.size(), p)) && clips.keeps(p);
        const int inExport = windingsAt(exported, 1, p)[0];
        check.kept += keep ? 1 : 0;
        check.mismatches += (inExport == 1) != keep ? 1 : 0;
        check.otherWindings += inExport != 0 && inExport != 1 ? 1 : 0;
    }
    return check;
}

// Pixels of the trim of `scene` under `settings` and of the export under the positive
// index rule that agree (both empty, or both covered at the same depth), over 20 views.
struct ViewAgreement {
    long covered = 0;
    long agreeing = 0;
};

ViewAgreement agreementFromViews(const Scene& scene, const TrimSettings& settings, const TrimmedSolid& solid)
{
    constexpr int kWidth = 64, kHeight = 48, kViews = 20;
    const Scene exported = exportedScene(solid);
    TrimSettings plain;
    plain.rule = StaticRule::PositiveIndex;
    const ReferenceRenderer original(scene);
    const ReferenceRenderer fromExport(exported);
    ViewAgreement agreement;
    for (int i = 0; i < kViews; ++i) {
        const Camera camera =
            fitCamera(scene.worldBounds(), double(kWidth) / kHeight, test::fibonacciDirection(i, kViews));
        const ReferenceResult a = original.render(camera, kWidth, kHeight, settings, 1);
        const ReferenceResult b = fromExport.render(camera, kWidth, kHeight, plain, 1);
        for (std::size_t p = 0; p < a.trim.pixels.size(); ++p) {
            const TrimPixel& x = a.trim.pixels[p];
            const TrimPixel& z = b.trim.pixels[p];
            if (!x.covered() && !z.covered())
                continue;
            ++agreement.covered;
            const bool same = x.covered() && z.covered() &&
                              std::abs(x.viewDepth - z.viewDepth) <= 1e-4f * std::max(x.viewDepth, 1e-3f);
            agreement.agreeing += same ? 1 : 0;
        }
    }
    return agreement;
}

Scene oneObject(const char* name, TriangleMesh mesh)
{
    Scene scene;
    scene.objects.push_back({name, std::move(mesh), glm::dmat4(1.0)});
    return scene;
}

Scene ballBitingSphere()
{
    Scene scene = oneObject("sphere", makeIcosphere(glm::dvec3(0.0), 1.0, 2));
    ObjectTransform placed;
    placed.translation = {0.7, 0.2, 0.1};
    placed.rotationDegrees = {0.0, 20.0, 0.0};
    placed.scale = 0.6;
    scene.objects.push_back({"ball", makeIcosphere(glm::dvec3(0.0), 1.0, 1), placed.modelMatrix()});
    return scene;
}

// Three icosahedra turned about the axis through the centre of one face: that face's
// plane holds three triangles overlapping in part (and other faces cross).
Scene coplanarTrio()
{
    const TriangleMesh icosahedron = makeIcosphere(glm::dvec3(0.0), 1.0, 0);
    const glm::uvec3 t = icosahedron.triangles.front();
    const glm::dvec3 a(icosahedron.positions[t.x]), b(icosahedron.positions[t.y]), c(icosahedron.positions[t.z]);
    const glm::dvec3 centre = (a + b + c) / 3.0;
    const glm::dvec3 axis = glm::normalize(glm::cross(b - a, c - a));
    const auto turned = [&](double radians) {
        return glm::translate(glm::dmat4(1.0), centre) * glm::rotate(glm::dmat4(1.0), radians, axis) *
               glm::translate(glm::dmat4(1.0), -centre);
    };
    Scene scene = oneObject("a", icosahedron);
    scene.objects.push_back({"b", icosahedron, turned(0.5)});
    scene.objects.push_back({"c", icosahedron, turned(1.1)});
    return scene;
}

// The hardest shape of the exact export's profile (EMBER case 582, a CAD part): long
// sliver triangles whose bounding boxes overlap by the thousand, most pairs of which
// meet nowhere or at a shared corner only. Here a long thin rod of slivers, pierced by a
// ball and a second rod crossing it.
Scene sliverRods()
{
    const std::array<glm::dvec2, 4> profile{glm::dvec2(0.0, -2.0), glm::dvec2(0.15, -2.0), glm::dvec2(0.15, 2.0),
                                            glm::dvec2(0.0, 2.0)};
    const TriangleMesh rod = makeSurfaceOfRevolution(profile, 96);
    Scene scene = oneObject("rod", rod);
    ObjectTransform crossing;
    crossing.rotationDegrees = {0.0, 0.0, 70.0};
    crossing.translation = {0.05, 0.3, 0.02};
    scene.objects.push_back({"crossing rod", rod, crossing.modelMatrix()});
    ObjectTransform ball;
    ball.translation = {0.1, -1.1, 0.0};
    ball.scale = 0.3;
    scene.objects.push_back({"ball", makeIcosphere(glm::dvec3(0.0), 1.0, 2), ball.modelMatrix()});
    return scene;
}

Scene sceneNamed(const QString& name)
{
    if (name == "sliver-rods")
        return sliverRods();
    if (name == "pushed-sphere")
        return oneObject("pushed", makePushedSphere(24, 14));
    if (name == "crossing-loop")
        return oneObject("loop", makeCrossingLoop(40, 10));
    if (name == "ball-sphere")
        return ballBitingSphere();
    if (name == "coplanar-trio")
        return coplanarTrio();
    // A shared mesh: the first meshes CGAL 5.5's experimental autorefinement refused (a
    // vertex of one triangle on another's edge).
    const LoadedScene loaded = loadScene(test::sharedDataPath(name.toStdString()).string());
    return loaded.scene;
}

} // namespace

Q_DECLARE_METATYPE(trimlab::StaticRule)

class TestTrimmedSolid : public QObject {
    Q_OBJECT
private slots:
    void matchesTheTrim_data();
    void matchesTheTrim();
    void coincidentOppositeFacesCancel();
    void profileCountsTheStages();
    void trimmingOffIsRefused();
    void clipPolytopeIsClosedAndConvex();
    void cutByClippingPlanesAsShown_data();
    void cutByClippingPlanesAsShown();
};

void TestTrimmedSolid::matchesTheTrim_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<StaticRule>("rule");
    QTest::addColumn<QString>("csg");
    QTest::addColumn<long>("openEdges");
    // Whether the 20 views must agree: not where objects have coincident faces and the
    // CSG tells them apart, because there the image-space trim meets two fragments at
    // one depth and classifies by whichever it takes first (a z-fight), while the export
    // is exact; the random samples check that case.
    QTest::addColumn<bool>("compareViews");
    for (StaticRule rule : {StaticRule::AlternatingBorder, StaticRule::Nonzero, StaticRule::PositiveIndex,
                            StaticRule::Negative, StaticRule::Parity})
        QTest::newRow(qPrintable("pushed sphere " + QString::fromStdString(ruleName(rule))))
            << "pushed-sphere" << rule << QString() << 0L << true;
    QTest::newRow("crossing loop w>=2") << "crossing-loop" << StaticRule::atLeast(2) << QString() << 0L << true;
    QTest::newRow("crossing loop positive") << "crossing-loop" << StaticRule::PositiveIndex << QString() << 0L << true;
    QTest::newRow("ball minus sphere") << "ball-sphere" << StaticRule::PositiveIndex << "1 - 0" << 0L << true;
    QTest::newRow("sphere minus ball") << "ball-sphere" << StaticRule::PositiveIndex << "0 - 1" << 0L << true;
    QTest::newRow("sphere and ball") << "ball-sphere" << StaticRule::PositiveIndex << "0 & 1" << 0L << true;
    QTest::newRow("coplanar trio nonzero") << "coplanar-trio" << StaticRule::Nonzero << QString() << 0L << true;
    QTest::newRow("coplanar trio a - b - c")
        << "coplanar-trio" << StaticRule::PositiveIndex << "0 - 1 - 2" << 0L << false;
    QTest::newRow("sliver rods nonzero") << "sliver-rods" << StaticRule::Nonzero << QString() << 0L << true;
    QTest::newRow("sliver rods minus ball")
        << "sliver-rods" << StaticRule::PositiveIndex << "(0 | 1) - 2" << 0L << true;
    QTest::newRow("cow alternating border")
        << "selfintersect/cgal-cow.off.gz" << StaticRule::AlternatingBorder << QString() << 0L << true;
}

void TestTrimmedSolid::matchesTheTrim()
{
    QFETCH(QString, scene);
    QFETCH(StaticRule, rule);
    QFETCH(QString, csg);
    QFETCH(long, openEdges);
    QFETCH(bool, compareViews);
    const Scene input = sceneNamed(scene);
    const TrimSettings settings = classification(rule, csg);
    const TrimmedSolid solid = trimmedSolid(input, settings);
    const TrimmedSolidStats& s = solid.stats;
    qInfo("%zu input triangles -> %zu refined faces (%zu pieces, %zu components) -> %zu kept; %zu open, %zu "
          "non-manifold edges; volume %.6f; %.0f + %.0f ms",
          s.inputTriangles, s.refinedFaces, s.boundaryPieces, s.components, s.keptFaces, s.openEdges,
          s.nonManifoldEdges, s.signedVolume, s.refineMs, s.windingMs);
    QCOMPARE(s.contradictions, std::size_t(0));
    QCOMPARE(long(s.openEdges), openEdges);
    QVERIFY(s.keptFaces > 0);
    QVERIFY(s.signedVolume > 0.0);

    // Random points: inside the export exactly where the scene's windings are kept.
    const SampleCheck samples = checkSamples(input, settings, solid, ClipSet{}, 7);
    const Bounds bounds = input.worldBounds();
    const double boxVolume =
        (bounds.max.x - bounds.min.x) * (bounds.max.y - bounds.min.y) * (bounds.max.z - bounds.min.z);
    qInfo("%d of %d samples kept (volume estimate %.4f, exported %.4f); %d disagree", samples.kept, kSamples,
          boxVolume * samples.kept / kSamples, s.signedVolume, samples.mismatches);
    QCOMPARE(samples.otherWindings, 0);
    QCOMPARE(samples.mismatches, 0);
    QVERIFY(samples.kept > 0);

    if (!compareViews)
        return;
    const ViewAgreement views = agreementFromViews(input, settings, solid);
    qInfo("views: %ld of %ld covered pixels agree", views.agreeing, views.covered);
    QVERIFY(views.covered > 500);
    QVERIFY2(views.agreeing >= views.covered * 999 / 1000,
             qPrintable(QString("%1 of %2").arg(views.agreeing).arg(views.covered)));
}

// A sphere and the same sphere turned inside out: in one object every face cancels; as
// two objects the faces stay (each object keeps its winding) but the scene's winding is
// 0 everywhere, so nothing is kept.
void TestTrimmedSolid::coincidentOppositeFacesCancel()
{
    const TriangleMesh sphere = makeIcosphere(glm::dvec3(0.0), 1.0, 1);
    TriangleMesh reversed = sphere;
    for (glm::uvec3& t : reversed.triangles)
        std::swap(t.y, t.z);
    TriangleMesh both = sphere;
    appendMesh(both, reversed);
    TrimSettings settings;
    settings.rule = StaticRule::Nonzero;
    const TrimmedSolid one = trimmedSolid(oneObject("both", both), settings);
    QCOMPARE(one.stats.keptFaces, std::size_t(0));
    QCOMPARE(one.stats.cancelledFaces, sphere.triangles.size());
    Scene two = oneObject("sphere", sphere);
    two.objects.push_back({"reversed", reversed, glm::dmat4(1.0)});
    const TrimmedSolid separate = trimmedSolid(two, settings);
    QCOMPARE(separate.stats.keptFaces, std::size_t(0));
    QCOMPARE(separate.stats.refinedFaces, sphere.triangles.size());
    QCOMPARE(separate.stats.contradictions, std::size_t(0));
}

// The profile's sizes follow the input: apart, two spheres give no pair to construct and
// nothing to split (their neighbours share edges and corners only); crossing slivers give pairs, constructions and split triangles, all
// bounded by the input; two boxes on one floor give
// groups of coplanar faces in the two planes they share. The stages' times add up
// to no more than the two phases they divide.
void TestTrimmedSolid::profileCountsTheStages()
{
    TrimSettings settings;
    settings.rule = StaticRule::Nonzero;
    Scene apart = oneObject("left", makeIcosphere(glm::dvec3(-2.0, 0.0, 0.0), 1.0, 1));
    apart.objects.push_back({"right", makeIcosphere(glm::dvec3(2.0, 0.0, 0.0), 1.0, 1), glm::dmat4(1.0)});
    const TrimmedSolidStats separate = trimmedSolid(apart, settings).stats;
    QVERIFY(separate.profile.candidatePairs > 0); // neighbours in each sphere: decided without constructing
    QCOMPARE(separate.profile.constructedPairs, std::size_t(0));
    QCOMPARE(separate.profile.splitTriangles, std::size_t(0));
    QCOMPARE(separate.profile.coplanarGroups, std::size_t(0));
    QCOMPARE(separate.profile.rays, std::size_t(2));

    const TrimmedSolidStats slivers = trimmedSolid(sliverRods(), settings).stats;
    const ExactProfile& p = slivers.profile;
    QVERIFY(p.constructedPairs > 0);
    QVERIFY(p.constructedPairs <= p.candidatePairs);
    QVERIFY(p.splitTriangles > 0);
    QVERIFY(p.splitTriangles <= slivers.inputTriangles);
    QVERIFY(p.sortedEdges > 0); // the rods' axis ends: every slice meets there
    QCOMPARE(p.rays, slivers.components);
    const double refineStages = p.pairsMs + p.constructMs + p.triangulateMs + p.mergeMs;
    const double windingStages = p.wedgesMs + p.walkMs + p.raysMs;
    for (double ms : {p.pairsMs, p.constructMs, p.triangulateMs, p.mergeMs, p.wedgesMs, p.walkMs, p.raysMs})
        QVERIFY(ms >= 0.0);
    QVERIFY2(refineStages <= slivers.refineMs + 1.0,
             qPrintable(QString("%1 of %2 ms").arg(refineStages).arg(slivers.refineMs)));
    QVERIFY2(windingStages <= slivers.windingMs + 1.0,
             qPrintable(QString("%1 of %2 ms").arg(windingStages).arg(slivers.windingMs)));

    // Two boxes on one floor, overlapping: their bottoms overlap in the plane z = 0 and so
    // do their tops in z = 1.
    Scene boxes = oneObject("box", makeBox(glm::dvec3(0.0), glm::dvec3(1.0)));
    boxes.objects.push_back(
        {"shifted", makeBox(glm::dvec3(0.5, 0.5, 0.0), glm::dvec3(1.5, 1.5, 1.0)), glm::dmat4(1.0)});
    const ExactProfile floors = trimmedSolid(boxes, settings).stats.profile;
    QVERIFY(floors.coplanarGroups >= 2); // at least one per plane
    QVERIFY(floors.largestCoplanarGroup >= 2);
    QVERIFY(floors.largestCoplanarGroup <= 4); // the four triangles of one plane at most
}

void TestTrimmedSolid::trimmingOffIsRefused()
{
    TrimSettings settings;
    settings.trimEnabled = false;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             (void)trimmedSolid(oneObject("sphere", makeIcosphere(glm::dvec3(0.0), 1.0, 1)), settings));
}

// The unit cube cut by z <= 0.5, then also by the slanted x + y <= 1: closed, outward,
// with the volumes 1/2 and 1/4; planes that keep nothing of the box give no mesh.
void TestTrimmedSolid::clipPolytopeIsClosedAndConvex()
{
    Bounds cube;
    cube.extend(glm::dvec3(0.0));
    cube.extend(glm::dvec3(1.0));
    ClipSet clips = ClipSet::single(ClipPlane{true, {0.0, 0.0, -1.0}, 0.5});
    const TriangleMesh half = clipPolytope(clips, cube);
    const MeshValidationReport halfReport = validateMesh(half);
    QVERIFY2(halfReport.trimmable() && halfReport.manifold(), formatReport(halfReport, "half").c_str());
    QCOMPARE(half.positions.size(), std::size_t(8));
    QVERIFY(std::abs(halfReport.signedVolume - 0.5) < 1e-6);
    clips.planes[1] = ClipPlane{true, {-1.0, -1.0, 0.0}, 1.0};
    const MeshValidationReport quarter = validateMesh(clipPolytope(clips, cube));
    QVERIFY2(quarter.trimmable() && quarter.genus == 0, formatReport(quarter, "quarter").c_str());
    QVERIFY2(std::abs(quarter.signedVolume - 0.25) < 1e-6, qPrintable(QString::number(quarter.signedVolume)));
    clips.planes[2] = ClipPlane{true, {0.0, 0.0, 1.0}, -2.0}; // z >= 2: nothing of the cube
    QVERIFY(clipPolytope(clips, cube).triangles.empty());
}

void TestTrimmedSolid::cutByClippingPlanesAsShown_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<StaticRule>("rule");
    QTest::addColumn<QString>("csg");
    QTest::newRow("pushed sphere, alternating border") << "pushed-sphere" << StaticRule::AlternatingBorder << "";
    QTest::newRow("ball bitten out of the sphere") << "ball-sphere" << StaticRule::Nonzero << "0 - 1";
}

// The solid as the view cut and capped shows it: closed; inside exactly where the rule
// keeps the scene and both planes keep the point; seen from 20 directions the same
// surfaces as the CPU reference of the cut, capped scene; and the two sides of one plane
// add up to the whole solid.
void TestTrimmedSolid::cutByClippingPlanesAsShown()
{
    QFETCH(QString, scene);
    QFETCH(StaticRule, rule);
    QFETCH(QString, csg);
    const Scene input = sceneNamed(scene);
    TrimSettings settings = classification(rule, csg);
    ClipSet clips;
    clips.planes[0] = ClipPlane{true, glm::normalize(glm::dvec3(0.2, -0.1, -1.0)), 0.05};
    clips.planes[1] = ClipPlane{true, {-1.0, 0.0, 0.0}, 0.6};
    settings.setClipSet(clips);
    settings.cap.enabled = true;
    const TrimmedSolid cut = cutTrimmedSolid(input, settings);
    const TrimmedSolidStats& s = cut.stats;
    qInfo("cut: %zu kept faces, %zu open, %zu non-manifold edges, volume %.6f", s.keptFaces, s.openEdges,
          s.nonManifoldEdges, s.signedVolume);
    QCOMPARE(s.openEdges, std::size_t(0));
    QCOMPARE(s.contradictions, std::size_t(0));
    QVERIFY(s.signedVolume > 0.0);

    const SampleCheck samples = checkSamples(input, settings, cut, clips, 11);
    QCOMPARE(samples.otherWindings, 0);
    QCOMPARE(samples.mismatches, 0);
    QVERIFY(samples.kept > 0);

    const ViewAgreement views = agreementFromViews(input, settings, cut);
    qInfo("views: %ld of %ld covered pixels agree", views.agreeing, views.covered);
    QVERIFY(views.covered > 500);
    QVERIFY2(views.agreeing >= views.covered * 999 / 1000,
             qPrintable(QString("%1 of %2").arg(views.agreeing).arg(views.covered)));

    TrimSettings one = settings;
    one.setClipSet(ClipSet::single(clips.planes[0]));
    TrimSettings other = settings;
    other.setClipSet(ClipSet::single(clips.planes[0].flipped()));
    const TrimmedSolid whole = trimmedSolid(input, settings);
    const double front = cutTrimmedSolid(input, one).stats.signedVolume;
    const double back = cutTrimmedSolid(input, other).stats.signedVolume;
    QVERIFY2(std::abs(front + back - whole.stats.signedVolume) <= 1e-5 * whole.stats.signedVolume,
             qPrintable(QStringLiteral("%1 + %2 vs %3").arg(front).arg(back).arg(whole.stats.signedVolume)));
    // Without a plane the cut is the whole solid.
    TrimSettings uncut = settings;
    uncut.setClipSet(ClipSet{});
    QCOMPARE(cutTrimmedSolid(input, uncut).mesh, whole.mesh);
}

QTEST_APPLESS_MAIN(TestTrimmedSolid)
#include "tst_trimmed_solid.moc"
