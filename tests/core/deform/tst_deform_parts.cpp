// The pieces of the space-warp brush one at a time: names, settings checks, falloff
// profiles, the angle term, closest surface points, the brush topology, local geodesics
// on flat grids (against exact Euclidean distances) and region smoothing on a plane.
#include "core/deform/angle_attenuation.h"
#include "core/deform/brush_settings_check.h"
#include "core/deform/brush_topology.h"
#include "core/deform/closest_surface_point.h"
#include "core/deform/falloff.h"
#include "core/deform/local_geodesics.h"
#include "core/deform/local_vertex_map.h"
#include "core/deform/region_patch.h"
#include "core/deform/region_smoothing.h"
#include "core/deform/stroke.h"

#include <QtTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

using namespace trimlab;
using namespace trimlab::deform;

namespace {

// An n×n-cell grid of the square [0, size]² in the z = 0 plane, each cell cut along
// alternating diagonals. `jitter` (a fraction of the cell) moves interior vertices in
// the plane by a fixed pseudo-random amount, giving an irregular but still flat mesh.
TriangleMesh flatGrid(int n, double size, double jitter = 0.0)
{
    TriangleMesh mesh;
    const double h = size / n;
    std::uint32_t state = 12345u;
    auto random = [&state] { // a fixed LCG: the same mesh on every platform
        state = state * 1664525u + 1013904223u;
        return double(state >> 8) / double(1u << 24) - 0.5;
    };
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            double x = i * h, y = j * h;
            if (i > 0 && j > 0 && i < n && j < n) {
                x += jitter * h * random();
                y += jitter * h * random();
            }
            mesh.positions.emplace_back(float(x), float(y), 0.0f);
        }
    }
    auto id = [n](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const std::uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            if ((i + j) % 2 == 0) {
                mesh.triangles.emplace_back(a, b, c);
                mesh.triangles.emplace_back(a, c, d);
            } else {
                mesh.triangles.emplace_back(a, b, d);
                mesh.triangles.emplace_back(b, c, d);
            }
        }
    }
    return mesh;
}

std::uint32_t triangleContaining(const TriangleMesh& mesh, const glm::dvec3& p)
{
    return closestSurfacePoint(mesh.positions, mesh.triangles, p).triangle;
}

struct GeodesicError {
    double maxRelative = 0.0;
    std::size_t missing = 0; // vertices clearly inside the radius that the front did not reach
};

// Local distances from `anchor` on a flat mesh against the exact (Euclidean) ones.
GeodesicError flatGeodesicError(const TriangleMesh& mesh, const glm::dvec3& anchor, double radius)
{
    const BrushTopology topology(mesh);
    const glm::uvec3 t = mesh.triangles[triangleContaining(mesh, anchor)];
    std::vector<GeodesicSeed> seeds;
    for (int i = 0; i < 3; ++i)
        seeds.push_back({t[i], glm::distance(anchor, glm::dvec3(mesh.positions[t[i]]))});
    const LocalDistances local = localGeodesicDistances(topology, mesh.positions, seeds, radius);

    GeodesicError error;
    for (std::size_t i = 0; i < local.vertices.size(); ++i) {
        const double exact = glm::distance(anchor, glm::dvec3(mesh.positions[local.vertices[i]]));
        error.maxRelative = std::max(error.maxRelative, std::abs(local.distances[i] - exact) / std::max(exact, 1e-3));
    }
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
        const double exact = glm::distance(anchor, glm::dvec3(mesh.positions[v]));
        if (exact < 0.99 * radius && !std::binary_search(local.vertices.begin(), local.vertices.end(), v))
            ++error.missing;
    }
    return error;
}

} // namespace

class TestDeformParts : public QObject {
    Q_OBJECT
private slots:
    void namesRoundTrip();
    void settingsChecks();
    void strokeEquality();
    void falloffProfiles_data();
    void falloffProfiles();
    void angleAttenuationCases();
    void closestPointOnTriangleMatchesSampling();
    void closestSurfacePointOnGrid();
    void topologyRingsAndFaces();
    void topologyRejectsBadIndices();
    void localVertexMapGrowsAndFinds();
    void unfoldedDistanceIsExactForAPointSource();
    void flatGeodesicsMatchEuclidean_data();
    void flatGeodesicsMatchEuclidean();
    void geodesicsStayLocal();
    void cotangentSmoothingKeepsAPlaneInPlace();
};

void TestDeformParts::namesRoundTrip()
{
    for (FalloffProfile p : {FalloffProfile::Smooth, FalloffProfile::Linear, FalloffProfile::Sharp})
        QCOMPARE(parseFalloffProfile(falloffProfileName(p)), std::optional(p));
    for (SmoothingWeights w : {SmoothingWeights::Uniform, SmoothingWeights::Cotangent})
        QCOMPARE(parseSmoothingWeights(smoothingWeightsName(w)), std::optional(w));
    QCOMPARE(falloffProfileName(FalloffProfile::Sharp), std::string_view("sharp"));
    QCOMPARE(smoothingWeightsName(SmoothingWeights::Cotangent), std::string_view("cotangent"));
    QVERIFY(!parseFalloffProfile("Smooth"));
    QVERIFY(!parseFalloffProfile(""));
    QVERIFY(!parseSmoothingWeights("cotan"));
}

void TestDeformParts::settingsChecks()
{
    QVERIFY(!brushSettingsError(BrushSettings{}));
    auto bad = [](auto change) {
        BrushSettings s;
        change(s);
        return brushSettingsError(s).has_value();
    };
    QVERIFY(bad([](BrushSettings& s) { s.radius = 0.0; }));
    QVERIFY(bad([](BrushSettings& s) { s.radius = -1.0; }));
    QVERIFY(bad([](BrushSettings& s) { s.radius = std::nan(""); }));
    QVERIFY(bad([](BrushSettings& s) { s.radius = std::numeric_limits<double>::infinity(); }));
    QVERIFY(bad([](BrushSettings& s) { s.strength = std::nan(""); }));
    QVERIFY(bad([](BrushSettings& s) { s.smoothingIterations = -1; }));
    QVERIFY(bad([](BrushSettings& s) { s.smoothingStep = 0.0; }));
    QVERIFY(bad([](BrushSettings& s) { s.smoothingStep = 1.5; }));
    QVERIFY(bad([](BrushSettings& s) { s.smoothingStep = std::nan(""); }));
    QVERIFY(bad([](BrushSettings& s) { s.profile = static_cast<FalloffProfile>(7); }));
    QVERIFY(bad([](BrushSettings& s) { s.smoothingWeights = static_cast<SmoothingWeights>(-1); }));
    QVERIFY(!bad([](BrushSettings& s) {
        s.strength = -2.0;
        s.smoothingStep = 1.0;
        s.smoothingIterations = 0;
    }));
    BrushSettings s;
    s.radius = -1.0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, requireValidBrushSettings(s));
}

void TestDeformParts::strokeEquality()
{
    Stroke a;
    a.anchor = glm::dvec3(1, 2, 3);
    a.anchorTriangle = 4u;
    a.drag = glm::dvec3(0, 0, 1);
    Stroke b = a;
    QVERIFY(a == b);
    b.brush.profile = FalloffProfile::Sharp;
    QVERIFY(!(a == b));
    b = a;
    b.anchorTriangle.reset();
    QVERIFY(a != b);
}

void TestDeformParts::falloffProfiles_data()
{
    QTest::addColumn<FalloffProfile>("profile");
    QTest::newRow("smooth") << FalloffProfile::Smooth;
    QTest::newRow("linear") << FalloffProfile::Linear;
    QTest::newRow("sharp") << FalloffProfile::Sharp;
}

void TestDeformParts::falloffProfiles()
{
    QFETCH(FalloffProfile, profile);
    QCOMPARE(falloff(profile, 0.0), 1.0);
    QCOMPARE(falloff(profile, -0.5), 1.0);
    QCOMPARE(falloff(profile, 1.0), 0.0);
    QCOMPARE(falloff(profile, 3.0), 0.0);
    QCOMPARE(falloff(profile, std::nan("")), 0.0);
    double previous = 1.0;
    for (int i = 1; i <= 1000; ++i) {
        const double f = falloff(profile, i / 1000.0);
        QVERIFY2(f <= previous && f >= 0.0, qPrintable(QString("t = %1").arg(i / 1000.0)));
        previous = f;
    }
    if (profile == FalloffProfile::Smooth) { // C¹: zero slope at both ends
        QVERIFY((1.0 - falloff(profile, 1e-4)) / 1e-4 < 1e-3);
        QVERIFY(falloff(profile, 1.0 - 1e-4) / 1e-4 < 1e-3);
    }
    if (profile == FalloffProfile::Sharp) // concentrated: below the cone everywhere inside
        QVERIFY(falloff(profile, 0.5) < falloff(FalloffProfile::Linear, 0.5));
}

void TestDeformParts::angleAttenuationCases()
{
    const glm::dvec3 up(0, 0, 1), side(1, 0, 0), down(0, 0, -1);
    // Pulling the surface out along its normal: the anchor and anything facing up move
    // fully, a side-on vertex half, a vertex facing away not at all.
    QCOMPARE(angleAttenuation(up, up, up), 1.0);
    QCOMPARE(angleAttenuation(side, up, up), 0.5);
    QCOMPARE(angleAttenuation(down, up, up), 0.0);
    // Pushing straight in: nobody faces the push less than the anchor.
    QCOMPARE(angleAttenuation(side, up, down), 1.0);
    QCOMPARE(angleAttenuation(down, up, down), 1.0);
    QCOMPARE(angleAttenuation(up, up, down), 1.0);
    // A tangential drag: vertices tilted against it are held back, monotonically.
    const glm::dvec3 tilted = glm::normalize(glm::dvec3(-1, 0, 1));
    const double a = angleAttenuation(tilted, up, side);
    QVERIFY(a > 0.0 && a < 1.0);
    QVERIFY(angleAttenuation(glm::normalize(glm::dvec3(-3, 0, 1)), up, side) < a);
    // No drag, no preference.
    QCOMPARE(angleAttenuation(down, up, glm::dvec3(0.0)), 1.0);
}

void TestDeformParts::closestPointOnTriangleMatchesSampling()
{
    const glm::dvec3 a(0.1, -0.2, 0.3), b(1.3, 0.2, -0.1), c(0.4, 1.1, 0.5);
    const glm::dvec3 queries[] = {{0.5, 0.4, 1.0},  {-1, -1, 0},     {2, 0.2, 0},      {0.4, 2, 0.5},
                                  {0.8, -0.5, 0.2}, {1.2, 1.0, 0.3}, {-0.5, 0.6, 0.4}, {0.6, 0.4, 0.2}};
    const int n = 200;
    for (const glm::dvec3& q : queries) {
        const glm::dvec3 p = closestPointOnTriangle(q, a, b, c);
        double sampled = std::numeric_limits<double>::infinity();
        for (int i = 0; i <= n; ++i) {
            for (int j = 0; i + j <= n; ++j) {
                const glm::dvec3 s = a + (double(i) / n) * (b - a) + (double(j) / n) * (c - a);
                sampled = std::min(sampled, glm::distance(q, s));
            }
        }
        // The exact answer is never farther than the best sample and at most one sample
        // spacing (|edge|/n ≈ 0.007) closer.
        const double d = glm::distance(q, p);
        QVERIFY2(d <= sampled + 1e-12 && d > sampled - 0.01, qPrintable(QString::number(d - sampled)));
        // p lies in the triangle's plane.
        QVERIFY(std::abs(glm::dot(p - a, glm::normalize(glm::cross(b - a, c - a)))) < 1e-12);
    }
    // A sliver (collinear corners) falls back to its edges.
    const glm::dvec3 p =
        closestPointOnTriangle(glm::dvec3(0.5, 1, 0), glm::dvec3(0), glm::dvec3(1, 0, 0), glm::dvec3(2, 0, 0));
    QCOMPARE(p, glm::dvec3(0.5, 0, 0));
}

void TestDeformParts::closestSurfacePointOnGrid()
{
    const TriangleMesh grid = flatGrid(8, 1.0);
    const SurfacePoint above = closestSurfacePoint(grid.positions, grid.triangles, glm::dvec3(0.3, 0.6, 0.25));
    QVERIFY(glm::distance(above.point, glm::dvec3(0.3, 0.6, 0.0)) < 1e-12);
    QCOMPARE(above.distance, 0.25);
    const glm::uvec3 t = grid.triangles[above.triangle];
    QCOMPARE(glm::distance(closestPointOnTriangle(above.point, glm::dvec3(grid.positions[t.x]),
                                                  glm::dvec3(grid.positions[t.y]), glm::dvec3(grid.positions[t.z])),
                           above.point),
             0.0);
    const SurfacePoint outside = closestSurfacePoint(grid.positions, grid.triangles, glm::dvec3(2.0, 0.5, 0.0));
    QVERIFY(glm::distance(outside.point, glm::dvec3(1.0, 0.5, 0.0)) < 1e-12);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)closestSurfacePoint(grid.positions, {}, glm::dvec3(0.0)));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             (void)closestSurfacePoint(grid.positions, grid.triangles, glm::dvec3(std::nan(""))));
}

void TestDeformParts::topologyRingsAndFaces()
{
    TriangleMesh grid = flatGrid(4, 1.0);
    grid.positions.emplace_back(5.0f, 5.0f, 5.0f); // an isolated vertex
    const BrushTopology topology(grid);
    QCOMPARE(topology.vertexCount(), grid.positions.size());
    QCOMPARE(topology.ringBegin(25), topology.ringEnd(25));
    QCOMPARE(topology.facesBegin(25), topology.facesEnd(25));
    // Interior vertex 6 = (1, 1) of a 4×4 grid with alternating diagonals: (1+1) is even,
    // so it has both diagonals of the cells it shares: 8 neighbours, 8 triangles.
    QCOMPARE(topology.ringEnd(6) - topology.ringBegin(6), 8);
    QCOMPARE(topology.facesEnd(6) - topology.facesBegin(6), 8);
    for (std::uint32_t v = 0; v < topology.vertexCount(); ++v) {
        QVERIFY(std::is_sorted(topology.ringBegin(v), topology.ringEnd(v)));
        QVERIFY(std::adjacent_find(topology.ringBegin(v), topology.ringEnd(v)) == topology.ringEnd(v));
        QVERIFY(std::is_sorted(topology.facesBegin(v), topology.facesEnd(v)));
        for (const std::uint32_t* u = topology.ringBegin(v); u != topology.ringEnd(v); ++u) {
            QVERIFY(*u != v);
            QVERIFY(std::binary_search(topology.ringBegin(*u), topology.ringEnd(*u), v)); // symmetric
        }
        for (const std::uint32_t* f = topology.facesBegin(v); f != topology.facesEnd(v); ++f) {
            const glm::uvec3 t = grid.triangles[*f];
            QVERIFY(t.x == v || t.y == v || t.z == v);
        }
    }
}

void TestDeformParts::topologyRejectsBadIndices()
{
    TriangleMesh mesh = flatGrid(2, 1.0);
    mesh.triangles.emplace_back(0u, 1u, 9u); // 9 vertices: 0..8
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, BrushTopology{mesh});
    // A repeated index is degenerate but legal: the vertex lists the triangle once.
    mesh.triangles.back() = glm::uvec3(0u, 0u, 1u);
    const BrushTopology topology(mesh);
    QCOMPARE(std::count(topology.facesBegin(0), topology.facesEnd(0), std::uint32_t(mesh.triangles.size() - 1)), 1);
}

void TestDeformParts::localVertexMapGrowsAndFinds()
{
    LocalVertexMap<double> map(4);
    // Clustered ids (as a region has) and far ones, through several growths.
    for (std::uint32_t v = 0; v < 3000; ++v)
        map[1000 + v * (v % 7 == 0 ? 977u : 1u)] = double(v);
    QCOMPARE(map.size(), std::size_t(3000));
    for (std::uint32_t v = 0; v < 3000; ++v) {
        const double* value = map.find(1000 + v * (v % 7 == 0 ? 977u : 1u));
        QVERIFY(value != nullptr);
        QCOMPARE(*value, double(v));
    }
    QVERIFY(map.find(999) == nullptr);
    QCOMPARE(map[999], 0.0); // inserted default
    QCOMPARE(map.size(), std::size_t(3001));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, map[0xFFFFFFFFu]);
}

void TestDeformParts::unfoldedDistanceIsExactForAPointSource()
{
    // Source at (0.3, −0.4, 0); triangle a = (0,0), b = (1,0), c = (0.6, 0.8) in z = 0,
    // then the same configuration rotated out of the xy plane.
    const glm::dvec3 s(0.3, -0.4, 0), a(0, 0, 0), b(1, 0, 0), c(0.6, 0.8, 0);
    const double d = unfoldedDistance(a, b, c, glm::distance(s, a), glm::distance(s, b));
    QVERIFY(std::abs(d - glm::distance(s, c)) < 1e-12);
    auto rotate = [](const glm::dvec3& p) { return glm::dvec3(p.x, 0.6 * p.y - 0.8 * p.z, 0.8 * p.y + 0.6 * p.z); };
    const double r = unfoldedDistance(rotate(a), rotate(b), rotate(c), glm::distance(s, a), glm::distance(s, b));
    QVERIFY(std::abs(r - glm::distance(s, c)) < 1e-12);
    // The line from a source far to the left does not enter through ab: no update.
    const glm::dvec3 far(-3.0, -0.1, 0);
    QCOMPARE(unfoldedDistance(a, b, glm::dvec3(0.2, 0.1, 0), glm::distance(far, a), glm::distance(far, b)),
             std::numeric_limits<double>::infinity());
    // Distances that no point can have (da + db < |ab|): no update.
    QCOMPARE(unfoldedDistance(a, b, c, 0.2, 0.2), std::numeric_limits<double>::infinity());
}

void TestDeformParts::flatGeodesicsMatchEuclidean_data()
{
    QTest::addColumn<double>("jitter");
    QTest::addColumn<double>("tolerance");
    // Tolerances: on the regular grid every distance comes from exact unfoldings, so only
    // rounding remains (measured 1e-9). On the jittered grid some straight lines leave a
    // triangle through a corner or an edge whose far corner settles late, and those
    // vertices take an edge step somewhere: measured 0.3%, bounded at 1%. (Edge paths
    // alone are off by up to 8% on any grid, as on an 8-connected lattice.)
    QTest::newRow("regular") << 0.0 << 1e-6;
    QTest::newRow("jittered") << 0.4 << 0.01;
}

void TestDeformParts::flatGeodesicsMatchEuclidean()
{
    QFETCH(double, jitter);
    QFETCH(double, tolerance);
    const TriangleMesh grid = flatGrid(60, 1.0, jitter);
    for (const glm::dvec3& anchor : {glm::dvec3(0.503, 0.497, 0), glm::dvec3(0.31, 0.62, 0)}) {
        const GeodesicError error = flatGeodesicError(grid, anchor, 0.3);
        QVERIFY2(error.maxRelative < tolerance, qPrintable(QString("max relative error %1").arg(error.maxRelative)));
        QCOMPARE(error.missing, std::size_t(0));
    }
}

void TestDeformParts::geodesicsStayLocal()
{
    const TriangleMesh grid = flatGrid(40, 1.0);
    const BrushTopology topology(grid);
    const GeodesicSeed seed{std::uint32_t(20 * 41 + 20), 0.0}; // the centre vertex
    const LocalDistances local = localGeodesicDistances(topology, grid.positions, {&seed, 1}, 0.1);
    QVERIFY(std::is_sorted(local.vertices.begin(), local.vertices.end()));
    QCOMPARE(local.vertices.size(), local.distances.size());
    // About π·0.1²/(1/40)² ≈ 50 vertices, certainly far fewer than the 1681 of the mesh.
    QVERIFY(local.vertices.size() > 30 && local.vertices.size() < 80);
    for (double d : local.distances)
        QVERIFY(d >= 0.0 && d < 0.1);
    const GeodesicSeed outside{0, 0.5};
    QVERIFY(localGeodesicDistances(topology, grid.positions, {&outside, 1}, 0.1).vertices.empty());
    const GeodesicSeed bad{99999, 0.0};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             (void)localGeodesicDistances(topology, grid.positions, {&bad, 1}, 0.1));
}

void TestDeformParts::cotangentSmoothingKeepsAPlaneInPlace()
{
    // On a plane the cotangent Laplacian of a Delaunay triangulation vanishes: smoothing
    // moves nothing (beyond rounding), while uniform weights slide vertices towards the
    // denser side. A graded rectilinear grid (x ← x²) cut into right triangles is Delaunay
    // and has unequal one-rings.
    TriangleMesh grid = flatGrid(10, 1.0);
    for (glm::vec3& p : grid.positions)
        p.x = p.x * p.x;
    const BrushTopology topology(grid);
    std::vector<std::uint32_t> region;
    for (std::uint32_t v = 0; v < grid.positions.size(); ++v) {
        const glm::vec3 p = grid.positions[v];
        if (p.x > 0.25f && p.x < 0.75f && p.y > 0.25f && p.y < 0.75f)
            region.push_back(v);
    }
    const RegionPatch patch(topology, region);
    QCOMPARE(patch.regionSize(), region.size());
    std::vector<glm::dvec3> start;
    for (std::size_t i = 0; i < patch.size(); ++i)
        start.emplace_back(grid.positions[patch.global(i)]);
    const std::vector<double> steps(region.size(), 1.0);

    std::vector<glm::dvec3> cot = start;
    smoothRegion(patch, cot, steps, SmoothingWeights::Cotangent, 5);
    std::vector<glm::dvec3> uniform = start;
    smoothRegion(patch, uniform, steps, SmoothingWeights::Uniform, 5);
    double cotMove = 0.0, uniformMove = 0.0;
    for (std::size_t i = 0; i < patch.size(); ++i) {
        cotMove = std::max(cotMove, glm::distance(cot[i], start[i]));
        uniformMove = std::max(uniformMove, glm::distance(uniform[i], start[i]));
        QCOMPARE(cot[i].z, 0.0);
        if (i >= patch.regionSize()) { // the halo is fixed
            QCOMPARE(cot[i], start[i]);
            QCOMPARE(uniform[i], start[i]);
        }
    }
    QVERIFY2(cotMove < 1e-9, qPrintable(QString::number(cotMove)));
    QVERIFY(uniformMove > 1e-3);
}

QTEST_APPLESS_MAIN(TestDeformParts)
#include "tst_deform_parts.moc"
