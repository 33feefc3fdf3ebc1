// Subdivision surfaces through stencil tables (core/surface/subdivision_surface.h),
// checked against OpenSubdiv evaluated along other paths: the patch table with PatchMap
// and EvaluateBasis at the same (ptex face, u, v), and the limit masks of the uniformly
// refined vertices (PrimvarRefiner::Limit). Plus counts, closedness and orientation,
// edits restricted to stencil supports, sharp features and the refusals.
#include "uniform_refinement.h"

#include "core/surface/cage_refiner.h"
#include "core/surface/subdivision_cages.h"
#include "core/surface/subdivision_surface.h"

#include "core/mesh/mesh_validation.h"

#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTable.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/stencilTable.h>

#include <QtTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <set>

using namespace trimlab;

namespace Far = OpenSubdiv::Far;

Q_DECLARE_METATYPE(trimlab::SubdivisionCage)

namespace {

using test::OsdPoint;

struct ReferencePoint {
    glm::dvec3 position, du, dv;
};

// The limit surface at `locations`, evaluated the way OpenSubdiv's patch tutorials do:
// adaptive refinement, every refined vertex interpolated level by level, the Gregory
// end caps' local points from the patch table's stencils, then PatchMap + EvaluateBasis.
std::vector<ReferencePoint> patchTableEvaluation(const SubdivisionCage& cage,
                                                 const std::vector<LimitLocation>& locations)
{
    const std::unique_ptr<Far::TopologyRefiner> refiner = createCageRefiner(cage);
    const Far::PatchTableFactory::Options options = limitPatchOptions();
    refiner->RefineAdaptive(options.GetRefineAdaptiveOptions());
    const std::unique_ptr<Far::PatchTable> patches(Far::PatchTableFactory::Create(*refiner, options));
    const int refined = refiner->GetNumVerticesTotal();
    std::vector<OsdPoint> points(std::size_t(refined + patches->GetNumLocalPoints()));
    for (std::size_t v = 0; v < cage.vertexCount(); ++v)
        points[v].p = cage.positions[v];
    const Far::PrimvarRefinerReal<double> primvars(*refiner);
    OsdPoint* source = points.data();
    for (int level = 1; level <= refiner->GetMaxLevel(); ++level) {
        OsdPoint* destination = source + refiner->GetLevel(level - 1).GetNumVertices();
        primvars.Interpolate(level, source, destination);
        source = destination;
    }
    if (patches->GetNumLocalPoints() > 0)
        patches->GetLocalPointStencilTable<double>()->UpdateValues(points.data(), points.data() + refined);
    const Far::PatchMap map(*patches);
    std::vector<ReferencePoint> result;
    for (const LimitLocation& l : locations) {
        const Far::PatchTable::PatchHandle* handle = map.FindPatch(int(l.ptexFace), l.u, l.v);
        if (!handle)
            return {};
        double wP[20], wDu[20], wDv[20];
        patches->EvaluateBasis(*handle, l.u, l.v, wP, wDu, wDv);
        const Far::ConstIndexArray cvs = patches->GetPatchVertices(*handle);
        ReferencePoint r{glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0)};
        for (int k = 0; k < cvs.size(); ++k) {
            r.position += wP[k] * points[std::size_t(cvs[k])].p;
            r.du += wDu[k] * points[std::size_t(cvs[k])].p;
            r.dv += wDv[k] * points[std::size_t(cvs[k])].p;
        }
        result.push_back(r);
    }
    return result;
}

// The limit positions and tangent-plane normals of the cage's uniform level-`level`
// vertices by OpenSubdiv's limit masks (PrimvarRefiner::Limit).
std::vector<ReferencePoint> limitMaskEvaluation(const SubdivisionCage& cage, int level)
{
    const test::UniformRefinement refined = test::refineUniformly(cage, level, true);
    const test::LimitPoints limit = test::limitOfRefined(refined);
    std::vector<ReferencePoint> result;
    for (std::size_t v = 0; v < refined.points.size(); ++v)
        result.push_back({limit.position[v].p, limit.du[v].p, limit.dv[v].p});
    return result;
}

// Two pentagons joined by five quads: valence-3 corners and, after one level, valence-5
// face points — the case that exercises ptex sub-faces.
SubdivisionCage pentagonalPrismCage()
{
    SubdivisionCage cage;
    for (int z = 0; z < 2; ++z)
        for (int k = 0; k < 5; ++k) {
            const double a = 2.0 * std::numbers::pi * k / 5.0;
            cage.positions.emplace_back(std::cos(a), std::sin(a), z == 0 ? -0.6 : 0.6);
        }
    cage.faceSizes = {5, 5, 4, 4, 4, 4, 4};
    cage.faceIndices = {4, 3, 2, 1, 0, 5, 6, 7, 8, 9};
    for (std::uint32_t k = 0; k < 5; ++k) {
        const std::uint32_t n = (k + 1) % 5;
        cage.faceIndices.insert(cage.faceIndices.end(), {k, n, n + 5, k + 5});
    }
    return cage;
}

SubdivisionCage allSharpCube()
{
    SubdivisionCage cage = cubeCage();
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (std::size_t f = 0; f < cage.faceCount(); ++f) {
        const auto face = cage.face(f);
        for (std::size_t k = 0; k < face.size(); ++k)
            edges.insert(std::minmax(face[k], face[(k + 1) % face.size()]));
    }
    for (const auto& [a, b] : edges)
        cage.creases.push_back({a, b, kInfiniteSharpness});
    return cage;
}

std::uint32_t cubeVertex(const SubdivisionCage& cube, glm::dvec3 p)
{
    return std::uint32_t(std::find(cube.positions.begin(), cube.positions.end(), p) - cube.positions.begin());
}

// The cube with its top face (z = 1) ringed by infinitely sharp edges, one vertical edge
// 2.5 sharp, and one infinitely sharp bottom corner.
SubdivisionCage creasedCube()
{
    SubdivisionCage cage = cubeCage();
    const glm::dvec3 ring[] = {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
    for (int k = 0; k < 4; ++k)
        cage.creases.push_back({cubeVertex(cage, ring[k]), cubeVertex(cage, ring[(k + 1) % 4]), kInfiniteSharpness});
    cage.creases.push_back({cubeVertex(cage, {1, 1, 1}), cubeVertex(cage, {1, 1, -1}), 2.5f});
    cage.corners.push_back({cubeVertex(cage, {-1, -1, -1}), kInfiniteSharpness});
    return cage;
}

std::set<std::uint32_t> changedVertices(const std::vector<glm::dvec3>& before, const std::vector<glm::dvec3>& after)
{
    std::set<std::uint32_t> changed;
    for (std::size_t v = 0; v < before.size(); ++v)
        if (before[v] != after[v])
            changed.insert(std::uint32_t(v));
    return changed;
}

// `forLimitMasks`: leave out the pentagonal prism at level 0 — Catmull–Clark limit masks
// assume quads around a vertex, so PrimvarRefiner::Limit is no reference there.
void addCageRows(bool forLimitMasks)
{
    QTest::addColumn<SubdivisionCage>("cage");
    QTest::addColumn<int>("level");
    QTest::newRow("cube L3") << cubeCage() << 3;
    QTest::newRow("cube L0") << cubeCage() << 0;
    QTest::newRow("t-shape L2") << tShapeCage() << 2;
    QTest::newRow("pentagonal prism L2") << pentagonalPrismCage() << 2;
    if (!forLimitMasks)
        QTest::newRow("pentagonal prism L0") << pentagonalPrismCage() << 0;
    QTest::newRow("torus 8x6 L2") << torusCage(8, 6) << 2;
    QTest::newRow("octahedron (Loop) L3") << octahedronCage() << 3;
    QTest::newRow("tetrahedron (Loop) L2") << tetrahedronCage() << 2;
    // No darts (a vertex on exactly one infinitely sharp edge): there OpenSubdiv's
    // patches and its limit masks differ by up to 6e-3 on this cube (measured).
    const SubdivisionCage creased = creasedCube();
    // Level 3: the 2.5-sharp crease has decayed to 0, so the limit masks apply exactly.
    QTest::newRow("creased cube L3") << creased << 3;
}

} // namespace

class TestSubdivisionSurface : public QObject {
    Q_OBJECT

private slots:
    void limitMatchesPatchTableEvaluation_data() { addCageRows(false); }
    void limitMatchesPatchTableEvaluation();
    void limitMatchesLimitMasks_data() { addCageRows(true); }
    void limitMatchesLimitMasks();
    void uniformCubeCountsAndTopology();
    void outputsAreClosedOrientedManifolds_data() { addCageRows(false); }
    void outputsAreClosedOrientedManifolds();
    void editChangesExactlyTheSupport_data();
    void editChangesExactlyTheSupport();
    void allSharpCubeStaysOnTheCube();
    void infinitelySharpCreaseIsKept();
    void loopRefusesQuads();
    void levelsAndSizeAreBounded();
    void evaluateRejectsBadPositions();
    void degenerateCageGivesNoNaN();
};

void TestSubdivisionSurface::limitMatchesPatchTableEvaluation()
{
    QFETCH(SubdivisionCage, cage);
    QFETCH(int, level);
    // Move the cage off its symmetric shape so that no check passes by symmetry.
    for (std::size_t v = 0; v < cage.vertexCount(); ++v)
        cage.positions[v] +=
            0.05 * glm::dvec3(std::sin(3.0 * double(v)), std::cos(5.0 * double(v)), std::sin(7.0 * double(v)));
    const SubdivisionSurface surface(cage, {level, SubdivisionMode::Limit});
    const std::vector<ReferencePoint> reference = patchTableEvaluation(cage, surface.limitLocations());
    QCOMPARE(reference.size(), surface.positions().size());
    double worstPosition = 0.0, worstNormal = 0.0;
    for (std::size_t v = 0; v < reference.size(); ++v) {
        worstPosition = std::max(worstPosition, glm::length(surface.positions()[v] - reference[v].position));
        worstPosition = std::max(worstPosition, glm::length(surface.tangentsU()[v] - reference[v].du));
        worstPosition = std::max(worstPosition, glm::length(surface.tangentsV()[v] - reference[v].dv));
        const glm::dvec3 n = glm::normalize(glm::cross(reference[v].du, reference[v].dv));
        worstNormal = std::max(worstNormal, glm::length(glm::dvec3(surface.normals()[v]) - n));
    }
    QVERIFY2(worstPosition < 1e-6, qPrintable(QString("position/tangent error %1").arg(worstPosition)));
    // Normals are stored as floats: 1e-6 is a few float ulps of a unit vector.
    QVERIFY2(worstNormal < 1e-6, qPrintable(QString("normal error %1").arg(worstNormal)));
}

void TestSubdivisionSurface::limitMatchesLimitMasks()
{
    QFETCH(SubdivisionCage, cage);
    QFETCH(int, level);
    for (std::size_t v = 0; v < cage.vertexCount(); ++v)
        cage.positions[v] +=
            0.05 * glm::dvec3(std::cos(2.0 * double(v)), std::sin(3.0 * double(v)), std::cos(5.0 * double(v)));
    const SubdivisionSurface surface(cage, {level, SubdivisionMode::Limit});
    const std::vector<ReferencePoint> masks = limitMaskEvaluation(cage, level);
    QCOMPARE(masks.size(), surface.positions().size());
    // Level-L vertices sit at ptex corners of patches isolated to level 4 ≥ L, where the
    // patches interpolate the exact limit position (regular B-spline patches, and the
    // Gregory end caps at extraordinary corners), so the two paths agree to rounding. A
    // wrong ptex location for a vertex would be off by a sizeable fraction of an edge.
    double worst = 0.0;
    double worstNormal = 0.0;
    for (std::size_t v = 0; v < masks.size(); ++v) {
        worst = std::max(worst, glm::length(surface.positions()[v] - masks[v].position));
        const glm::dvec3 n = glm::normalize(glm::cross(masks[v].du, masks[v].dv));
        worstNormal = std::max(worstNormal, glm::length(glm::dvec3(surface.normals()[v]) - n));
    }
    QVERIFY2(worst < 1e-9, qPrintable(QString("limit position error %1").arg(worst)));
    // Normals: the Gregory end caps interpolate the limit position at an extraordinary
    // corner but only approximate its tangent plane (measured: up to 6e-4 on the
    // pentagonal prism, 6e-5 on the cube), so this checks orientation and the tangent
    // plane to 1e-3; the exact normal check is the patch-table comparison above.
    // On a sharp crease or corner the surface has no single normal (each side has its own;
    // ours is the side of the face the vertex's location lies in), so only smooth cages.
    if (cage.creases.empty() && cage.corners.empty())
        QVERIFY2(worstNormal < 1e-3, qPrintable(QString("normal error %1").arg(worstNormal)));
}

void TestSubdivisionSurface::uniformCubeCountsAndTopology()
{
    for (int level = 0; level <= SubdivisionSurface::kMaxLevel; ++level) {
        const SubdivisionSurface surface(cubeCage(), {level, SubdivisionMode::Uniform});
        const std::size_t quads = std::size_t(6) << (2 * level);
        QCOMPARE(surface.mesh().triangleCount(), 2 * quads);
        QCOMPARE(surface.mesh().vertexCount(), quads + 2); // Euler: V − 2F + F = 2
        const MeshValidationReport report = validateMesh(surface.mesh());
        QVERIFY2(report.trimmable(), report.trimUnavailableReason().c_str());
        QVERIFY(report.manifold());
        QCOMPARE(report.genus.value_or(-1), std::int64_t(0));
        QVERIFY(report.signedVolume > 0.0);
    }
}

void TestSubdivisionSurface::outputsAreClosedOrientedManifolds()
{
    QFETCH(SubdivisionCage, cage);
    QFETCH(int, level);
    const std::int64_t genus = cage.faceCount() == 48 ? 1 : 0; // the 8×6 torus
    for (const SubdivisionMode mode : {SubdivisionMode::Uniform, SubdivisionMode::Limit}) {
        const SubdivisionSurface surface(cage, {level, mode});
        const MeshValidationReport report = validateMesh(surface.mesh());
        QVERIFY2(report.trimmable(), report.trimUnavailableReason().c_str());
        QVERIFY(report.manifold());
        QCOMPARE(report.genus.value_or(-1), genus);
        QVERIFY(report.signedVolume > 0.0); // outward, like the cage
        // Normals agree with the mesh's own orientation everywhere.
        const std::vector<glm::vec3> meshNormals = vertexNormals(surface.mesh());
        for (std::size_t v = 0; v < meshNormals.size(); ++v) {
            QVERIFY(std::isfinite(surface.normals()[v].x));
            QVERIFY2(glm::dot(surface.normals()[v], meshNormals[v]) > 0.0f, qPrintable(QString("vertex %1").arg(v)));
        }
    }
}

void TestSubdivisionSurface::editChangesExactlyTheSupport_data()
{
    QTest::addColumn<SubdivisionCage>("cage");
    QTest::addColumn<int>("mode");
    QTest::newRow("torus limit") << torusCage(12, 8) << int(SubdivisionMode::Limit);
    QTest::newRow("torus uniform") << torusCage(12, 8) << int(SubdivisionMode::Uniform);
    QTest::newRow("t-shape limit") << tShapeCage() << int(SubdivisionMode::Limit);
    QTest::newRow("octahedron limit") << octahedronCage() << int(SubdivisionMode::Limit);
}

void TestSubdivisionSurface::editChangesExactlyTheSupport()
{
    QFETCH(SubdivisionCage, cage);
    QFETCH(int, mode);
    SubdivisionSurface surface(cage, {2, SubdivisionMode(mode)});
    const std::uint32_t moved = 3;
    const std::vector<glm::dvec3> before = surface.positions();
    cage.positions[moved] += glm::dvec3(0.31, -0.17, 0.23);
    const std::uint32_t movedList[] = {moved};
    const std::vector<std::uint32_t> reported = surface.update(cage.positions, movedList);
    const std::set<std::uint32_t> changed = changedVertices(before, surface.positions());

    std::set<std::uint32_t> weighted; // output vertices whose stencil names the moved vertex
    for (std::uint32_t v = 0; v < surface.positions().size(); ++v)
        for (const StencilWeight& w : surface.positionStencil(v))
            if (w.cageVertex == moved && w.weight != 0.0)
                weighted.insert(v);
    const std::span<const std::uint32_t> support = surface.support(moved);
    QVERIFY(!changed.empty());
    if (cage.vertexCount() >= 20) // on a cage this size one vertex moves a local patch only
        QVERIFY(changed.size() < surface.positions().size() / 2);
    QCOMPARE(changed, weighted);
    QCOMPARE(std::set<std::uint32_t>(support.begin(), support.end()), changed);
    QCOMPARE(std::set<std::uint32_t>(reported.begin(), reported.end()), changed);
    QVERIFY(std::is_sorted(support.begin(), support.end()));

    // The sparse update equals, to the bit, a surface built from scratch on the moved cage
    // (same stencil sums, same normal sums), normals of the untouched vertices included.
    const SubdivisionSurface fresh(cage, {2, SubdivisionMode(mode)});
    for (std::size_t v = 0; v < before.size(); ++v) {
        QVERIFY(surface.positions()[v] == fresh.positions()[v]);
        QVERIFY2(surface.normals()[v] == fresh.normals()[v], qPrintable(QString("normal of vertex %1").arg(v)));
    }
    QCOMPARE(surface.mesh(), fresh.mesh());
}

void TestSubdivisionSurface::allSharpCubeStaysOnTheCube()
{
    for (const SubdivisionMode mode : {SubdivisionMode::Uniform, SubdivisionMode::Limit}) {
        const SubdivisionSurface surface(allSharpCube(), {4, mode});
        // Every point on the cube's surface: the largest |coordinate| is 1, none exceeds it.
        double worst = 0.0;
        for (const glm::dvec3& p : surface.positions())
            worst = std::max(worst, std::abs(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) - 1.0));
        QVERIFY2(worst < 1e-9, qPrintable(QString("off the cube by %1").arg(worst)));
    }
    // Without the creases the same cage shrinks well inside the cube.
    const SubdivisionSurface smooth(cubeCage(), {4, SubdivisionMode::Limit});
    double nearest = 1.0;
    for (const glm::dvec3& p : smooth.positions())
        nearest = std::min(nearest, std::abs(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) - 1.0));
    QVERIFY(nearest > 0.05);
}

void TestSubdivisionSurface::infinitelySharpCreaseIsKept()
{
    // The four edges of the cube's top face (z = 1) infinitely sharp: a closed crease ring
    // whose limit is a cubic B-spline curve of four coplanar points, so it stays in the
    // plane z = 1 while everything else is pulled below it.
    SubdivisionCage cage = cubeCage();
    for (std::size_t f = 0; f < cage.faceCount(); ++f) {
        const auto face = cage.face(f);
        if (std::all_of(face.begin(), face.end(), [&](std::uint32_t v) { return cage.positions[v].z == 1.0; }))
            for (std::size_t k = 0; k < face.size(); ++k)
                cage.creases.push_back({face[k], face[(k + 1) % face.size()], kInfiniteSharpness});
    }
    QCOMPARE(cage.creases.size(), std::size_t(4));
    for (const SubdivisionMode mode : {SubdivisionMode::Uniform, SubdivisionMode::Limit}) {
        const SubdivisionSurface surface(cage, {3, mode});
        std::size_t onRing = 0;
        double highest = -1.0;
        for (const glm::dvec3& p : surface.positions()) {
            highest = std::max(highest, p.z);
            if (std::abs(p.z - 1.0) < 1e-12)
                ++onRing;
        }
        // The ring fences the top face off: every refined point inside it is an average of
        // points of that face only, so the whole face — (2^3 + 1)² vertices — stays flat.
        QCOMPARE(onRing, std::size_t(9 * 9));
        QVERIFY(highest < 1.0 + 1e-12);
    }
}

void TestSubdivisionSurface::loopRefusesQuads()
{
    SubdivisionCage cage = cubeCage();
    cage.scheme = SubdivisionScheme::Loop;
    try {
        const SubdivisionSurface surface(cage, {2, SubdivisionMode::Limit});
        QFAIL("a quad cage was accepted for Loop subdivision");
    } catch (const SubdivisionError& e) {
        QCOMPARE(QString(e.what()), QString("Loop subdivision needs triangles, but cage face 0 has 4 corners; "
                                            "triangulate the cage or use Catmull-Clark"));
        QVERIFY(e.element() && e.element()->kind == CageElement::Kind::Face && e.element()->index == 0);
    }
}

void TestSubdivisionSurface::levelsAndSizeAreBounded()
{
    for (const int level : {-1, 6}) {
        try {
            const SubdivisionSurface surface(cubeCage(), {level, SubdivisionMode::Uniform});
            QFAIL("a level outside 0..5 was accepted");
        } catch (const SubdivisionError& e) {
            QCOMPARE(QString(e.what()), QString("subdivision level %1 is outside 0 to 5").arg(level));
        }
    }
    QElapsedTimer timer;
    timer.start();
    try {
        // 64×65 quads at level 5: 8,519,680 triangles, just above the cap of 8,388,608.
        const SubdivisionSurface surface(torusCage(64, 65), {5, SubdivisionMode::Limit});
        QFAIL("a result above the triangle cap was accepted");
    } catch (const SubdivisionError& e) {
        QCOMPARE(QString(e.what()), QString("subdivision level 5 of this cage would make 8519680 triangles "
                                            "(at most 8388608); use a lower level"));
    }
    QVERIFY(timer.elapsed() < 2000); // refused before any refinement
}

void TestSubdivisionSurface::evaluateRejectsBadPositions()
{
    const SubdivisionCage cage = cubeCage();
    SubdivisionSurface surface(cage, {1, SubdivisionMode::Limit});
    std::vector<glm::dvec3> tooFew(cage.positions.begin(), cage.positions.end() - 1);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, surface.evaluate(tooFew));
    std::vector<glm::dvec3> nan = cage.positions;
    nan[2].y = std::nan("");
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, surface.evaluate(nan));
    const std::uint32_t outOfRange[] = {8};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, surface.update(cage.positions, outOfRange));
    QVERIFY(surface.support(8).empty());
}

void TestSubdivisionSurface::degenerateCageGivesNoNaN()
{
    SubdivisionCage cage = cubeCage();
    for (glm::dvec3& p : cage.positions)
        p = glm::dvec3(0.5, 0.5, 0.5); // every vertex in one point
    for (const SubdivisionMode mode : {SubdivisionMode::Uniform, SubdivisionMode::Limit}) {
        const SubdivisionSurface surface(cage, {2, mode});
        for (std::size_t v = 0; v < surface.positions().size(); ++v) {
            QVERIFY(glm::length(surface.positions()[v] - glm::dvec3(0.5)) < 1e-12);
            const glm::vec3 n = surface.normals()[v];
            QVERIFY(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
        }
    }
}

QTEST_GUILESS_MAIN(TestSubdivisionSurface)
#include "tst_subdivision_surface.moc"
