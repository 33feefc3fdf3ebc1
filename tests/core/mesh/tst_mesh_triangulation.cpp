// Polygon triangulation: n − 2 triangles that tile the polygon without flips, for convex,
// non-convex, non-planar, collinear and degenerate polygons in any orientation.
#include "core/mesh/polygon_triangulation.h"

#include <QtTest>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <cmath>
#include <numeric>

using namespace trimlab;

namespace {

struct Polygon {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> corners;
};

// A polygon in the z = 0 plane from 2D points, corners 0..n−1 in the given order.
Polygon planar(const std::vector<glm::vec2>& points)
{
    Polygon polygon;
    for (const glm::vec2& p : points)
        polygon.positions.emplace_back(p.x, p.y, 0.0f);
    polygon.corners.resize(points.size());
    std::iota(polygon.corners.begin(), polygon.corners.end(), 0u);
    return polygon;
}

std::vector<glm::uvec3> triangulate(const Polygon& polygon)
{
    std::vector<glm::uvec3> triangles;
    triangulatePolygon(polygon.positions, polygon.corners, triangles);
    return triangles;
}

glm::dvec3 triangleNormal(const Polygon& polygon, const glm::uvec3& t)
{
    const glm::dvec3 a(polygon.positions[t[0]]), b(polygon.positions[t[1]]), c(polygon.positions[t[2]]);
    return glm::cross(b - a, c - a);
}

// Checks the triangulation tiles the polygon: n − 2 triangles over the polygon's corners,
// none facing against `normal`, their areas summing to `area`.
void checkTiling(const Polygon& polygon, const std::vector<glm::uvec3>& triangles, const glm::dvec3& normal,
                 double area)
{
    QCOMPARE(triangles.size(), polygon.corners.size() - 2);
    double sum = 0.0;
    for (const glm::uvec3& t : triangles) {
        for (int k = 0; k < 3; ++k)
            QVERIFY(t[k] < polygon.positions.size());
        const double along = glm::dot(triangleNormal(polygon, t), normal);
        QVERIFY2(along >= 0.0, qPrintable(QString("triangle (%1, %2, %3) is flipped").arg(t[0]).arg(t[1]).arg(t[2])));
        sum += 0.5 * along;
    }
    QVERIFY2(std::abs(sum - area) < 1e-9 * std::max(1.0, area),
             qPrintable(QString("area %1, expected %2").arg(sum).arg(area)));
}

} // namespace

class TestMeshTriangulation : public QObject {
    Q_OBJECT
private slots:
    void triangleIsKept();
    void convexQuadUsesFirstDiagonal();
    void dartQuadUsesTheInteriorDiagonal();
    void lShapeFromAHiddenCorner();
    void combWithManyReflexCorners();
    void collinearCornersOnTheBoundary();
    void clockwisePolygonKeepsItsOrientation();
    void tiltedNonPlanarHexagon();
    void degeneratePolygonFallsBackToAFan();
    void hugePolygonIsFanned();
    void soupTriangulatesEveryPolygon();
};

void TestMeshTriangulation::triangleIsKept()
{
    const Polygon p = planar({{0, 0}, {1, 0}, {0, 1}});
    QCOMPARE(triangulate(p), (std::vector<glm::uvec3>{{0, 1, 2}}));
}

void TestMeshTriangulation::convexQuadUsesFirstDiagonal()
{
    const Polygon p = planar({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    QCOMPARE(triangulate(p), (std::vector<glm::uvec3>{{0, 1, 2}, {0, 2, 3}}));
}

void TestMeshTriangulation::dartQuadUsesTheInteriorDiagonal()
{
    // Reflex corner 3: the diagonal 0–2 runs outside, so 1–3 must be used.
    const Polygon p = planar({{0, 0}, {2, 1}, {0, 2}, {0.5f, 1}});
    const std::vector<glm::uvec3> triangles = triangulate(p);
    QCOMPARE(triangles, (std::vector<glm::uvec3>{{1, 2, 3}, {1, 3, 0}}));
    checkTiling(p, triangles, {0, 0, 1}, 1.5);
}

void TestMeshTriangulation::lShapeFromAHiddenCorner()
{
    // Listed from (2,1), which cannot see (0,2) or (1,2): a fan would flip a triangle.
    const Polygon p = planar({{2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 0}, {2, 0}});
    checkTiling(p, triangulate(p), {0, 0, 1}, 3.0);
}

void TestMeshTriangulation::combWithManyReflexCorners()
{
    // A comb: base 0..7 × 0..1 with four teeth 1 wide and 2 high over x = 0, 2, 4, 6.
    const std::vector<glm::vec2> points = {{7, 0}, {7, 3}, {6, 3}, {6, 1}, {5, 1}, {5, 3}, {4, 3}, {4, 1},
                                           {3, 1}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}, {0, 0}};
    const Polygon p = planar(points);
    checkTiling(p, triangulate(p), {0, 0, 1}, 7.0 + 4 * 2.0);
}

void TestMeshTriangulation::collinearCornersOnTheBoundary()
{
    const Polygon p = planar({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}});
    checkTiling(p, triangulate(p), {0, 0, 1}, 4.0);
}

void TestMeshTriangulation::clockwisePolygonKeepsItsOrientation()
{
    // The L shape listed clockwise seen from +z: every triangle must face −z.
    const Polygon p = planar({{2, 0}, {0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}});
    checkTiling(p, triangulate(p), {0, 0, -1}, 3.0);
}

void TestMeshTriangulation::tiltedNonPlanarHexagon()
{
    // An L hexagon in the plane x + y + z = 0 (approximately), slightly warped.
    Polygon p = planar({{2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 0}, {2, 0}});
    const glm::dvec3 u = glm::normalize(glm::dvec3(1, -1, 0));
    const glm::dvec3 v = glm::normalize(glm::dvec3(1, 1, -2));
    for (std::size_t i = 0; i < p.positions.size(); ++i) {
        const glm::vec3 q = p.positions[i];
        const double warp = i % 2 ? 0.01 : -0.01;
        p.positions[i] = glm::vec3(double(q.x) * u + double(q.y) * v + warp * glm::cross(u, v));
    }
    const std::vector<glm::uvec3> triangles = triangulate(p);
    QCOMPARE(triangles.size(), std::size_t(4));
    for (const glm::uvec3& t : triangles)
        QVERIFY(glm::dot(triangleNormal(p, t), glm::cross(u, v)) > 0.0);
}

void TestMeshTriangulation::degeneratePolygonFallsBackToAFan()
{
    const Polygon line = planar({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}});
    QCOMPARE(triangulate(line), (std::vector<glm::uvec3>{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
    Polygon repeated = planar({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 1}});
    repeated.corners = {0, 1, 2, 3, 3};
    QCOMPARE(triangulate(repeated).size(), std::size_t(3));
}

void TestMeshTriangulation::hugePolygonIsFanned()
{
    std::vector<glm::vec2> circle;
    const std::size_t n = kMaxEarClippingCorners + 1;
    for (std::size_t i = 0; i < n; ++i) {
        const double angle = 2.0 * M_PI * double(i) / double(n);
        circle.emplace_back(std::cos(angle), std::sin(angle));
    }
    const Polygon p = planar(circle);
    const std::vector<glm::uvec3> triangles = triangulate(p);
    QCOMPARE(triangles.size(), n - 2);
    QCOMPARE(triangles.back(), glm::uvec3(0, std::uint32_t(n - 2), std::uint32_t(n - 1)));
}

void TestMeshTriangulation::soupTriangulatesEveryPolygon()
{
    const Polygon square = planar({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}});
    PolygonSoup soup;
    soup.corners = {0, 1, 2};
    soup.closePolygon();
    soup.corners.insert(soup.corners.end(), {0, 4, 2, 3});
    soup.closePolygon();
    QCOMPARE(soup.polygonCount(), std::size_t(2));
    QCOMPARE(soup.triangleCount(), std::size_t(3));
    QCOMPARE(soup.polygon(1).size(), std::size_t(4));
    const std::vector<glm::uvec3> triangles = triangulatePolygons(square.positions, soup);
    QCOMPARE(triangles.size(), std::size_t(3));
    QCOMPARE(triangles.front(), glm::uvec3(0, 1, 2));
}

QTEST_APPLESS_MAIN(TestMeshTriangulation)
#include "tst_mesh_triangulation.moc"
