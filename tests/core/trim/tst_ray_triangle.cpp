// The watertight ray-triangle test: hits, misses, facing, t and barycentrics, exact signs,
// and the single-hit tie-break for rays exactly through shared edges and vertices.
#include "core/scene/shape_generators.h"
#include "core/trim/ray_triangle.h"

#include <glm/geometric.hpp>

#include <QtTest>

#include <array>
#include <map>
#include <random>
#include <vector>

using namespace trimlab;

namespace {

__extension__ typedef __int128 Int128;

struct Tri {
    glm::dvec3 a, b, c;
};

std::vector<Tri> trianglesOf(const TriangleMesh& mesh)
{
    std::vector<Tri> out;
    for (const glm::uvec3& t : mesh.triangles)
        out.push_back(
            {glm::dvec3(mesh.positions[t[0]]), glm::dvec3(mesh.positions[t[1]]), glm::dvec3(mesh.positions[t[2]])});
    return out;
}

// Regular octahedron |x|+|y|+|z| = 1, outward.
TriangleMesh octahedron()
{
    TriangleMesh mesh;
    mesh.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (unsigned sx : {0u, 1u})
        for (unsigned sy : {2u, 3u})
            for (unsigned sz : {4u, 5u}) {
                const bool positive = (sx == 0) == ((sy == 2) == (sz == 4)); // sx·sy·sz > 0
                mesh.triangles.push_back(positive ? glm::uvec3(sx, sy, sz) : glm::uvec3(sx, sz, sy));
            }
    return mesh;
}

struct RayCount {
    int hits = 0;
    int facingSum = 0;
};

RayCount castThrough(const std::vector<Tri>& tris, const glm::dvec3& origin, const glm::dvec3& target)
{
    const WatertightRay ray = makeWatertightRay({origin, target - origin});
    RayCount count;
    for (const Tri& t : tris) {
        if (const auto hit = intersectTriangle(ray, t.a, t.b, t.c); hit && hit->t > 0.0) {
            ++count.hits;
            count.facingSum += hit->facing;
        }
    }
    return count;
}

// Whether every triangle containing `point` (a vertex or edge midpoint) is clearly front-
// or back-facing for direction d, with both kinds absent/present as on a non-silhouette.
bool awayFromSilhouette(const std::vector<Tri>& tris, const std::vector<std::size_t>& incident, const glm::dvec3& d)
{
    int sign = 0;
    for (std::size_t i : incident) {
        const Tri& t = tris[i];
        const glm::dvec3 n = glm::normalize(glm::cross(t.b - t.a, t.c - t.a));
        const double c = glm::dot(n, glm::normalize(d));
        if (std::abs(c) < 0.05)
            return false;
        const int s = c < 0.0 ? 1 : -1;
        if (sign != 0 && s != sign)
            return false;
        sign = s;
    }
    return true;
}

} // namespace

class TestRayTriangle : public QObject {
    Q_OBJECT
private slots:
    void hitWithKnownTAndBarycentrics();
    void missesAndEdgeOn();
    void reportsHitsBehindOrigin();
    void facingTAndBarycentricsRandom();
    void exactSignOfProducts();
    void zeroEdgeTieBreakTable();
    void planarGridEdgesAndVerticesHitOnce();
    void closedMeshesThroughEdgesAndVertices_data();
    void closedMeshesThroughEdgesAndVertices();
    void closedMeshRandomRaysBalance();
};

void TestRayTriangle::hitWithKnownTAndBarycentrics()
{
    const glm::dvec3 a(-1, -1, -5), b(1, -1, -5), c(0, 1, -5);
    const auto hit = intersectTriangle(makeWatertightRay({glm::dvec3(0.0), {0, 0, -1}}), a, b, c);
    QVERIFY(hit.has_value());
    QCOMPARE(hit->t, 5.0);
    QCOMPARE(hit->facing, 1); // (b−a)×(c−a) = +z, direction −z: counter-clockwise seen from the eye
    // (0,0,−5) = (1−u−v)a + u b + v c  =>  v = 1/2, u = 1/4 (solved by hand).
    QCOMPARE(hit->u, 0.25);
    QCOMPARE(hit->v, 0.5);
    // The same triangle wound the other way is back-facing, same t.
    const auto back = intersectTriangle(makeWatertightRay({glm::dvec3(0.0), {0, 0, -1}}), a, c, b);
    QVERIFY(back.has_value());
    QCOMPARE(back->facing, -1);
    QCOMPARE(back->t, 5.0);
    // Direction scaled by 2: t halves (t is the ray parameter, not a distance).
    const auto scaled = intersectTriangle(makeWatertightRay({glm::dvec3(0.0), {0, 0, -2}}), a, b, c);
    QVERIFY(scaled.has_value());
    QCOMPARE(scaled->t, 2.5);
}

void TestRayTriangle::missesAndEdgeOn()
{
    const glm::dvec3 a(-1, -1, -5), b(1, -1, -5), c(0, 1, -5);
    QVERIFY(!intersectTriangle(makeWatertightRay({glm::dvec3(0.0), {5, 0, -5}}), a, b, c));
    QVERIFY(!intersectTriangle(makeWatertightRay({glm::dvec3(0.0), {0, 1.01, -5}}), a, b, c));
    // A ray in the triangle's own plane sees it edge-on: no hit.
    QVERIFY(!intersectTriangle(makeWatertightRay({glm::dvec3(-3, 0, -5), {1, 0, 0}}), a, b, c));
    // Degenerate (collinear) triangle.
    QVERIFY(!intersectTriangle(makeWatertightRay({glm::dvec3(0.0), {0, 0, -1}}), a, b, 0.5 * (a + b)));
    // Non-finite input.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    QVERIFY(!intersectTriangle(makeWatertightRay({glm::dvec3(0.0), {0, 0, -1}}), a, b, glm::dvec3(nan, 0, -5)));
}

void TestRayTriangle::reportsHitsBehindOrigin()
{
    const auto hit = intersectTriangle(makeWatertightRay({glm::dvec3(0, 0, -10), {0, 0, -1}}), {-1, -1, -5},
                                       {1, -1, -5}, {0, 1, -5});
    QVERIFY(hit.has_value());
    QCOMPARE(hit->t, -5.0);
}

void TestRayTriangle::facingTAndBarycentricsRandom()
{
    std::mt19937 rng(1234);
    std::uniform_real_distribution<double> coord(-3.0, 3.0);
    std::uniform_real_distribution<double> unit(0.02, 1.0);
    for (int i = 0; i < 5000; ++i) {
        const glm::dvec3 a(coord(rng), coord(rng), coord(rng));
        const glm::dvec3 b(coord(rng), coord(rng), coord(rng));
        const glm::dvec3 c(coord(rng), coord(rng), coord(rng));
        const glm::dvec3 n = glm::cross(b - a, c - a);
        if (glm::length(n) < 0.1)
            continue;
        double wb = unit(rng), wc = unit(rng), wa = unit(rng);
        const double sum = wa + wb + wc;
        wa /= sum, wb /= sum, wc /= sum;
        const glm::dvec3 p = wa * a + wb * b + wc * c;
        const glm::dvec3 origin(coord(rng) * 3.0, coord(rng) * 3.0, coord(rng) * 3.0);
        const double tExpected = 0.5 + unit(rng) * 3.0;
        const glm::dvec3 direction = (p - origin) / tExpected;
        if (std::abs(glm::dot(glm::normalize(n), glm::normalize(direction))) < 0.05)
            continue; // nearly edge-on: t is ill-conditioned
        const auto hit = intersectTriangle(makeWatertightRay({origin, direction}), a, b, c);
        QVERIFY2(hit.has_value(), qPrintable(QString("case %1").arg(i)));
        QCOMPARE(hit->facing, glm::dot(n, direction) < 0.0 ? 1 : -1);
        QVERIFY(std::abs(hit->t - tExpected) < 1e-9 * tExpected + 1e-12);
        QVERIFY(std::abs(hit->u - wb) < 1e-9);
        QVERIFY(std::abs(hit->v - wc) < 1e-9);
    }
}

void TestRayTriangle::exactSignOfProducts()
{
    // (1 + 2^-27)(1 − 2^-27) = 1 − 2^-54 rounds to 1: the naive difference with 1·1 is 0.
    const double e = std::ldexp(1.0, -27);
    QCOMPARE((1.0 + e) * (1.0 - e) - 1.0 * 1.0, 0.0);
    QCOMPARE(exactSignOfDifferenceOfProducts(1.0 + e, 1.0 - e, 1.0, 1.0), -1);
    QCOMPARE(exactSignOfDifferenceOfProducts(1.0, 1.0, 1.0 + e, 1.0 - e), 1);
    QCOMPARE(exactSignOfDifferenceOfProducts(3.0, 5.0, 5.0, 3.0), 0);
    QCOMPARE(exactSignOfDifferenceOfProducts(0.1, 0.3, 0.3, 0.1), 0);
    QCOMPARE(exactSignOfDifferenceOfProducts(-2.0, 3.0, 1.0, 1.0), -1);
    // Random 50-bit integers: exact reference in 128-bit integer arithmetic.
    std::mt19937_64 rng(99);
    std::uniform_int_distribution<std::int64_t> big(-(std::int64_t(1) << 50), std::int64_t(1) << 50);
    for (int i = 0; i < 20000; ++i) {
        const std::int64_t p = big(rng), q = big(rng), r = big(rng);
        // Half the cases are built to be (nearly) zero: s = round(p q / r) +- {0, 1}.
        std::int64_t s = big(rng);
        const Int128 nearZero = r != 0 ? (Int128(p) * q) / r + (i % 3) - 1 : 0;
        if (i % 2 == 0 && nearZero > -(Int128(1) << 52) && nearZero < (Int128(1) << 52))
            s = std::int64_t(nearZero); // exactly representable as a double
        const Int128 exact = Int128(p) * q - Int128(r) * s;
        const int expected = (exact > 0) - (exact < 0);
        QCOMPARE(exactSignOfDifferenceOfProducts(double(p), double(q), double(r), double(s)), expected);
    }
}

void TestRayTriangle::zeroEdgeTieBreakTable()
{
    // dy > 0, or dy == 0 and dx < 0; the reversed edge always decides the other way.
    QVERIFY(ownsZeroEdge(0, 0, 0, 1));
    QVERIFY(!ownsZeroEdge(0, 1, 0, 0));
    QVERIFY(ownsZeroEdge(0, 0, -1, 0));
    QVERIFY(!ownsZeroEdge(-1, 0, 0, 0));
    QVERIFY(ownsZeroEdge(5, 0, -3, 1e-300));
    QVERIFY(!ownsZeroEdge(0, 0, 0, 0)); // a zero-length edge owns nothing
}

// A planar grid z = −4 of unit squares, each split along a diagonal (alternating), seen
// from the origin. Rays aimed exactly at every interior vertex and every edge midpoint:
// the shear is exact here, so edge functions are exactly zero and only the tie-break
// decides. Each such ray must hit exactly one triangle.
void TestRayTriangle::planarGridEdgesAndVerticesHitOnce()
{
    const int n = 6; // vertices -3..3
    std::vector<Tri> tris;
    std::vector<std::pair<glm::dvec3, glm::dvec3>> edges;
    auto v = [](int i, int j) { return glm::dvec3(i, j, -4.0); };
    for (int i = -n / 2; i < n / 2; ++i)
        for (int j = -n / 2; j < n / 2; ++j) {
            const bool flip = (i + j) % 2 != 0;
            const glm::dvec3 p00 = v(i, j), p10 = v(i + 1, j), p11 = v(i + 1, j + 1), p01 = v(i, j + 1);
            if (flip) {
                tris.push_back({p00, p10, p01});
                tris.push_back({p10, p11, p01});
                edges.push_back({p10, p01});
            } else {
                tris.push_back({p00, p10, p11});
                tris.push_back({p00, p11, p01});
                edges.push_back({p00, p11});
            }
            edges.push_back({p00, p10});
            edges.push_back({p00, p01});
        }
    int rays = 0;
    for (const auto& [p, q] : edges) {
        const glm::dvec3 mid = 0.5 * (p + q);
        if (std::abs(mid.x) >= n / 2 - 0.25 || std::abs(mid.y) >= n / 2 - 0.25)
            continue; // boundary edge of the grid
        for (const glm::dvec3& origin : {glm::dvec3(0.0), glm::dvec3(0.0, 0.0, 4.0)}) {
            const RayCount count = castThrough(tris, origin, mid);
            QVERIFY2(count.hits == 1,
                     qPrintable(QString("edge midpoint (%1, %2): %3 hits").arg(mid.x).arg(mid.y).arg(count.hits)));
            ++rays;
        }
    }
    for (int i = -n / 2 + 1; i < n / 2; ++i)
        for (int j = -n / 2 + 1; j < n / 2; ++j) {
            const RayCount count = castThrough(tris, glm::dvec3(0.0), v(i, j));
            QVERIFY2(count.hits == 1, qPrintable(QString("vertex (%1, %2): %3 hits").arg(i).arg(j).arg(count.hits)));
            // The same through a non-exact ray origin (exercises the exact-sign fallback).
            const RayCount skew = castThrough(tris, glm::dvec3(0.1, 0.3, 0.7), v(i, j));
            QCOMPARE(skew.hits, 1);
            rays += 2;
        }
    qInfo("%d rays through grid edges and vertices", rays);
}

void TestRayTriangle::closedMeshesThroughEdgesAndVertices_data()
{
    QTest::addColumn<int>("shape");
    QTest::newRow("octahedron") << 0;
    QTest::newRow("icosphere-2") << 1;
    QTest::newRow("uv-sphere-5x12") << 2;
    QTest::newRow("torus") << 3;
}

// Rays from several exterior origins exactly through every vertex and edge midpoint of a
// closed mesh: the hits of each ray balance (front = back), and a ray through a point
// away from the silhouette of a convex mesh hits it exactly twice.
void TestRayTriangle::closedMeshesThroughEdgesAndVertices()
{
    QFETCH(int, shape);
    const TriangleMesh mesh = shape == 0   ? octahedron()
                              : shape == 1 ? makeIcosphere(glm::dvec3(0.0), 1.0, 2)
                              : shape == 2 ? makeUvSphere(glm::dvec3(0.0), 1.0, 5, 12)
                                           : makeTorus(glm::dvec3(0.0), 1.0, 0.4, 12, 8);
    const bool convex = shape != 3;
    const std::vector<Tri> tris = trianglesOf(mesh);
    // Targets: each vertex and each edge midpoint, with their incident triangles.
    std::map<std::pair<unsigned, unsigned>, std::vector<std::size_t>> edgeTris;
    std::vector<std::vector<std::size_t>> vertexTris(mesh.positions.size());
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const unsigned a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
            edgeTris[std::minmax(a, b)].push_back(f);
            vertexTris[a].push_back(f);
        }
    std::vector<std::pair<glm::dvec3, std::vector<std::size_t>>> targets;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
        targets.push_back({glm::dvec3(mesh.positions[i]), vertexTris[i]});
    for (const auto& [edge, incident] : edgeTris)
        targets.push_back(
            {0.5 * (glm::dvec3(mesh.positions[edge.first]) + glm::dvec3(mesh.positions[edge.second])), incident});
    const glm::dvec3 origins[] = {{0, 0, 5}, {0, 5, 0}, {3.1, -2.7, 1.3}, {-4, 0.5, -2}, {0, 0, -5}};
    int twice = 0;
    for (const glm::dvec3& origin : origins)
        for (const auto& [target, incident] : targets) {
            const RayCount count = castThrough(tris, origin, target);
            QVERIFY2(count.facingSum == 0, qPrintable(QString("unbalanced ray to (%1, %2, %3): %4 hits, sum %5")
                                                          .arg(target.x)
                                                          .arg(target.y)
                                                          .arg(target.z)
                                                          .arg(count.hits)
                                                          .arg(count.facingSum)));
            if (convex && awayFromSilhouette(tris, incident, target - origin)) {
                QCOMPARE(count.hits, 2);
                ++twice;
            }
        }
    if (convex)
        QVERIFY(twice > int(targets.size()));
}

// Random rays from outside through a closed torus: always balanced.
void TestRayTriangle::closedMeshRandomRaysBalance()
{
    const std::vector<Tri> tris = trianglesOf(makeTorus(glm::dvec3(0.0), 1.0, 0.4, 24, 12));
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coord(-1.5, 1.5);
    for (int i = 0; i < 3000; ++i) {
        const glm::dvec3 origin(coord(rng) * 4.0, 6.0, coord(rng) * 4.0);
        const glm::dvec3 target(coord(rng), coord(rng) * 0.3, coord(rng));
        QCOMPARE(castThrough(tris, origin, target).facingSum, 0);
    }
}

QTEST_APPLESS_MAIN(TestRayTriangle)
#include "tst_ray_triangle.moc"
