// TriangleBvh::intersectAll must return exactly the hits of a brute-force loop over all
// world triangles with the same watertight test: every hit, none twice, same numbers.
#include "core/scene/shape_generators.h"
#include "core/trim/ray_triangle.h"
#include "core/trim/triangle_bvh.h"

#include <glm/gtc/matrix_transform.hpp>

#include <QtTest>

#include <algorithm>
#include <random>

using namespace trimlab;

namespace {

// Several objects with non-trivial model matrices, a random triangle soup, a degenerate
// triangle and duplicated geometry (exact ties).
Scene randomishScene()
{
    Scene scene;
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(0.3, -0.2, 0.1));
    m = glm::rotate(m, 0.7, glm::dvec3(1.0, 2.0, 0.5));
    scene.objects.push_back({"sphere", makeUvSphere(glm::dvec3(0.0), 1.0, 20, 30), m});
    scene.objects.push_back({"torus", makeTorus(glm::dvec3(0.5, 0.2, 0.0), 1.2, 0.3, 40, 16),
                             glm::scale(glm::dmat4(1.0), glm::dvec3(1.0, 1.5, 0.8))});
    TriangleMesh soup;
    std::mt19937 rng(4242);
    std::uniform_real_distribution<float> coord(-2.0f, 2.0f);
    std::uniform_real_distribution<float> offset(-0.3f, 0.3f);
    for (unsigned i = 0; i < 400; ++i) {
        const glm::vec3 c(coord(rng), coord(rng), coord(rng));
        for (int k = 0; k < 3; ++k)
            soup.positions.push_back(c + glm::vec3(offset(rng), offset(rng), offset(rng)));
        soup.triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2});
    }
    soup.positions.push_back({0, 0, 0});
    soup.triangles.push_back({0, 0, 1}); // repeated index: skipped
    scene.objects.push_back({"soup", soup, glm::dmat4(1.0)});
    scene.objects.push_back({"sphere-again", scene.objects[0].mesh, m}); // coincident copy
    return scene;
}

std::vector<RayHit> bruteForce(const std::vector<BvhTriangle>& tris, const PixelRay& ray, double tMin, double tMax)
{
    const WatertightRay w = makeWatertightRay(ray);
    std::vector<RayHit> hits;
    for (const BvhTriangle& t : tris) {
        if (const auto hit = intersectTriangle(w, t.a, t.b, t.c); hit && hit->t >= tMin && hit->t <= tMax)
            hits.push_back({hit->t, t.objectId, t.primitiveId, hit->facing, hit->u, hit->v});
    }
    std::sort(hits.begin(), hits.end(), walkOrder);
    return hits;
}

bool sameHits(const std::vector<RayHit>& a, const std::vector<RayHit>& b)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].t != b[i].t || a[i].objectId != b[i].objectId || a[i].primitiveId != b[i].primitiveId ||
            a[i].facing != b[i].facing || a[i].u != b[i].u || a[i].v != b[i].v)
            return false;
    }
    return true;
}

} // namespace

class TestTriangleBvh : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void structureIsConsistent();
    void randomRaysMatchBruteForce();
    void axisAlignedAndVertexRaysMatchBruteForce();
    void rangeIsInclusiveAndFiltered();
    void nearestIsTheSmallestOfAllHits();
    void emptyScene();

private:
    Scene m_scene;
    std::vector<BvhTriangle> m_triangles;
};

void TestTriangleBvh::initTestCase()
{
    m_scene = randomishScene();
    m_triangles = collectWorldTriangles(m_scene);
}

void TestTriangleBvh::structureIsConsistent()
{
    const TriangleBvh bvh(m_scene);
    QCOMPARE(bvh.triangleCount(), m_triangles.size());
    QCOMPARE(m_triangles.size(), m_scene.triangleCount() - 1); // the repeated-index triangle is skipped
    // Every triangle sits in exactly one leaf, inside that leaf's box.
    std::vector<int> seen(bvh.triangleCount(), 0);
    for (const BvhNode& node : bvh.nodes()) {
        for (std::uint32_t i = node.index; node.count > 0 && i < node.index + node.count; ++i) {
            ++seen[i];
            const BvhTriangle& t = bvh.triangles()[i];
            for (const glm::dvec3& p : {t.a, t.b, t.c})
                QVERIFY(glm::all(glm::lessThanEqual(node.lower, p)) && glm::all(glm::lessThanEqual(p, node.upper)));
        }
    }
    QVERIFY(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
    QVERIFY(bvh.depth() < 40);
    qInfo("%zu triangles, %zu nodes, depth %d", bvh.triangleCount(), bvh.nodeCount(), bvh.depth());
}

void TestTriangleBvh::randomRaysMatchBruteForce()
{
    const TriangleBvh bvh(m_scene);
    std::mt19937 rng(2024);
    std::uniform_real_distribution<double> coord(-4.0, 4.0);
    std::uniform_real_distribution<double> inner(-1.5, 1.5);
    std::size_t totalHits = 0;
    for (int i = 0; i < 3000; ++i) {
        const glm::dvec3 origin(coord(rng), coord(rng), coord(rng));
        const glm::dvec3 target(inner(rng), inner(rng), inner(rng));
        const PixelRay ray{origin, (target - origin) * (0.5 + 0.1 * (i % 7))};
        std::vector<RayHit> hits;
        bvh.intersectAll(ray, 0.0, 1e30, hits);
        std::sort(hits.begin(), hits.end(), walkOrder);
        const std::vector<RayHit> expected = bruteForce(m_triangles, ray, 0.0, 1e30);
        QVERIFY2(sameHits(hits, expected),
                 qPrintable(QString("ray %1: %2 vs %3 hits").arg(i).arg(hits.size()).arg(expected.size())));
        totalHits += hits.size();
    }
    qInfo("%zu hits compared", totalHits);
    QVERIFY(totalHits > 5000);
}

// Directions with zero components (the slab test's division by zero) and rays exactly
// through vertices (hits on box faces and corners).
void TestTriangleBvh::axisAlignedAndVertexRaysMatchBruteForce()
{
    const TriangleBvh bvh(m_scene);
    std::mt19937 rng(77);
    std::uniform_real_distribution<double> coord(-1.5, 1.5);
    const glm::dvec3 axes[] = {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {1, 1, 0}, {0, -1, 1}, {1, 0, -1}};
    for (int i = 0; i < 1200; ++i) {
        PixelRay ray;
        if (i % 2 == 0) {
            const glm::dvec3 d = axes[i % 6];
            ray = {glm::dvec3(coord(rng), coord(rng), coord(rng)) - 5.0 * d, d};
        } else {
            const BvhTriangle& t = m_triangles[std::size_t(i * 7919) % m_triangles.size()];
            const glm::dvec3 corner = i % 3 == 0 ? t.a : i % 3 == 1 ? t.b : t.c;
            const glm::dvec3 origin = (i % 4 == 1) ? glm::dvec3(corner.x, corner.y, 6.0) : glm::dvec3(5, -4, 3);
            ray = {origin, corner - origin};
        }
        std::vector<RayHit> hits;
        bvh.intersectAll(ray, 0.0, 1e30, hits);
        std::sort(hits.begin(), hits.end(), walkOrder);
        QVERIFY2(sameHits(hits, bruteForce(m_triangles, ray, 0.0, 1e30)), qPrintable(QString("ray %1").arg(i)));
    }
}

// intersectNearest against the smallest t of intersectAll, on rays from outside, from inside
// the closed objects (the skeleton's chords), along the axes, through vertices, and with
// ranges that start or end at a hit (inclusive at both ends).
void TestTriangleBvh::nearestIsTheSmallestOfAllHits()
{
    const TriangleBvh bvh(m_scene);
    std::mt19937 rng(5150);
    std::uniform_real_distribution<double> coord(-4.0, 4.0);
    std::uniform_real_distribution<double> inner(-1.5, 1.5);
    const glm::dvec3 axes[] = {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}};
    std::size_t found = 0;
    std::size_t missed = 0;
    for (int i = 0; i < 3000; ++i) {
        const glm::dvec3 origin = i % 3 == 0 ? glm::dvec3(inner(rng), inner(rng), inner(rng)) * 0.3
                                             : glm::dvec3(coord(rng), coord(rng), coord(rng));
        const glm::dvec3 direction = i % 5 == 0   ? axes[i % 3]
                                     : i % 5 == 1 ? m_triangles[std::size_t(i * 7919) % m_triangles.size()].b - origin
                                                  : glm::dvec3(inner(rng), inner(rng), inner(rng)) - origin;
        const PixelRay ray{origin, direction};
        std::vector<RayHit> all;
        bvh.intersectAll(ray, 0.0, 1e30, all);
        std::sort(all.begin(), all.end(), walkOrder);
        // The whole ray, then ranges cut at the second hit: from it (inclusive) and to it.
        std::vector<std::array<double, 2>> ranges{{0.0, 1e30}};
        if (all.size() >= 2)
            ranges.insert(ranges.end(), {{all[1].t, 1e30}, {0.0, all[1].t}, {all[1].t, all[1].t}});
        for (const auto& [tMin, tMax] : ranges) {
            std::optional<double> expected;
            for (const RayHit& hit : all)
                if (hit.t >= tMin && hit.t <= tMax && (!expected || hit.t < *expected))
                    expected = hit.t;
            const std::optional<RayHit> nearest = bvh.intersectNearest(ray, tMin, tMax);
            QVERIFY2(nearest.has_value() == expected.has_value(), qPrintable(QString("ray %1").arg(i)));
            if (!nearest) {
                ++missed;
                continue;
            }
            ++found;
            QVERIFY2(
                nearest->t == *expected,
                qPrintable(
                    QString("ray %1: t %2 against %3").arg(i).arg(nearest->t, 0, 'g', 17).arg(*expected, 0, 'g', 17)));
            // The hit itself is one of intersectAll's, with its numbers.
            QVERIFY(std::any_of(all.begin(), all.end(), [&](const RayHit& h) {
                return h.t == nearest->t && h.objectId == nearest->objectId && h.primitiveId == nearest->primitiveId &&
                       h.facing == nearest->facing && h.u == nearest->u && h.v == nearest->v;
            }));
        }
    }
    qInfo("%zu nearest hits compared, %zu rays or ranges without a hit", found, missed);
    QVERIFY(found > 3000 && missed > 100);
    QVERIFY(!bvh.intersectNearest(PixelRay{{0, 0, 0}, {1, 0, 0}}, 1.0, 0.0)); // empty range
}

void TestTriangleBvh::rangeIsInclusiveAndFiltered()
{
    const TriangleBvh bvh(m_scene);
    const PixelRay ray{{0.05, 0.02, 6.0}, {0.0, 0.0, -1.0}};
    std::vector<RayHit> all;
    bvh.intersectAll(ray, 0.0, 1e30, all);
    std::sort(all.begin(), all.end(), walkOrder);
    QVERIFY(all.size() >= 4);
    const double tMin = all[1].t;
    const double tMax = all[all.size() - 2].t;
    std::vector<RayHit> some;
    bvh.intersectAll(ray, tMin, tMax, some);
    std::sort(some.begin(), some.end(), walkOrder);
    QVERIFY(sameHits(some, bruteForce(m_triangles, ray, tMin, tMax)));
    QCOMPARE(some.front().t, tMin); // both ends inclusive
    QCOMPARE(some.back().t, tMax);
    // Appends, does not clear.
    bvh.intersectAll(ray, tMin, tMax, some);
    QCOMPARE(some.size(), 2 * bruteForce(m_triangles, ray, tMin, tMax).size());
}

void TestTriangleBvh::emptyScene()
{
    const TriangleBvh bvh{Scene{}};
    std::vector<RayHit> hits;
    bvh.intersectAll({glm::dvec3(0.0), {0, 0, -1}}, 0.0, 100.0, hits);
    QVERIFY(hits.empty());
    QCOMPARE(bvh.nodeCount(), std::size_t(0));
}

QTEST_APPLESS_MAIN(TestTriangleBvh)
#include "tst_triangle_bvh.moc"
