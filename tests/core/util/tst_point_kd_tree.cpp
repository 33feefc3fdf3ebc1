// Nearest-neighbour queries of the kd-tree (core/util/point_kd_tree.h) against a brute-force
// scan of the same points: random clouds, clustered and duplicated points (ties), the
// excluded index, non-finite points and queries, and the trees too small to split.
#include "core/util/point_kd_tree.h"

#include <QtTest>

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <random>

using namespace trimlab;

namespace {

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

/// The expected answer, by definition: the smallest squared distance, then the lowest index.
NearestPoint bruteForce(const std::vector<glm::dvec3>& points, const glm::dvec3& query, std::size_t excluded)
{
    NearestPoint best;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::dvec3 d = points[i] - query;
        const double distanceSquared = d.x * d.x + d.y * d.y + d.z * d.z;
        if (i == excluded || !std::isfinite(distanceSquared))
            continue;
        if (distanceSquared < best.distanceSquared)
            best = {i, distanceSquared};
    }
    return best;
}

std::vector<glm::dvec3> randomPoints(std::mt19937& random, std::size_t count, double scale)
{
    std::uniform_real_distribution<double> coordinate(-scale, scale);
    std::vector<glm::dvec3> points(count);
    for (glm::dvec3& p : points)
        p = {coordinate(random), coordinate(random), coordinate(random)};
    return points;
}

void compareWithBruteForce(const std::vector<glm::dvec3>& points, const std::vector<glm::dvec3>& queries)
{
    const PointKdTree tree(points);
    for (std::size_t q = 0; q < queries.size(); ++q) {
        // Half the queries exclude a point: the one the query is nearest to, the case the
        // shrinking balls use (a vertex's own position is excluded from its ball).
        const std::size_t excluded = q % 2 == 0 ? kNone : bruteForce(points, queries[q], kNone).index;
        const NearestPoint expected = bruteForce(points, queries[q], excluded);
        const NearestPoint found = tree.nearest(queries[q], excluded);
        QVERIFY2(found.index == expected.index && found.distanceSquared == expected.distanceSquared,
                 qPrintable(QString("query %1: tree gives point %2 at %3, brute force %4 at %5")
                                .arg(q)
                                .arg(found.index)
                                .arg(found.distanceSquared)
                                .arg(expected.index)
                                .arg(expected.distanceSquared)));

        // Bounded and away from a neighbourhood, as the shrinking balls ask: within the
        // distance to the 5th point of the list, leaving out everything near the 9th.
        const glm::dvec3 around = points[(q * 7 + 9) % points.size()];
        const glm::dvec3 toBound = points[(q * 3 + 5) % points.size()] - queries[q];
        const double belowSquared = glm::dot(toBound, toBound);
        const double aroundSquared = 0.04 * double(q % 5);
        NearestPoint away;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const glm::dvec3 d = points[i] - queries[q];
            const glm::dvec3 fromAround = points[i] - around;
            const double distanceSquared = glm::dot(d, d);
            if (std::isfinite(distanceSquared) && glm::dot(fromAround, fromAround) >= aroundSquared &&
                distanceSquared < belowSquared && distanceSquared < away.distanceSquared)
                away = {i, distanceSquared};
        }
        const NearestPoint foundAway = tree.nearestAwayFrom(queries[q], belowSquared, around, aroundSquared);
        QVERIFY2(foundAway.index == away.index && foundAway.found() == away.found(),
                 qPrintable(QString("query %1 away from a neighbourhood: tree gives point %2, brute force %3")
                                .arg(q)
                                .arg(foundAway.index)
                                .arg(away.index)));
    }
}

} // namespace

class TestPointKdTree : public QObject {
    Q_OBJECT

private slots:
    void randomCloudMatchesBruteForce()
    {
        std::mt19937 random(7);
        const std::vector<glm::dvec3> points = randomPoints(random, 2000, 1.0);
        // Queries inside the cloud, far outside it and exactly on its points.
        std::vector<glm::dvec3> queries = randomPoints(random, 300, 1.2);
        for (const glm::dvec3& p : randomPoints(random, 20, 50.0))
            queries.push_back(p);
        for (std::size_t i = 0; i < points.size(); i += 97)
            queries.push_back(points[i]);
        compareWithBruteForce(points, queries);
    }

    void flatAndDuplicatedPointsTieToTheLowerIndex()
    {
        // A grid in one plane (every split on the other axes is degenerate) with every
        // point present twice: each query has exact ties, which go to the lower index.
        std::vector<glm::dvec3> points;
        for (int copy = 0; copy < 2; ++copy)
            for (int i = 0; i < 12; ++i)
                for (int j = 0; j < 12; ++j)
                    points.push_back({0.25 * i, 0.25 * j, 0.0});
        std::vector<glm::dvec3> queries;
        for (int i = 0; i < 24; ++i)
            for (int j = 0; j < 24; ++j)
                queries.push_back({0.125 * i, 0.125 * j, 0.125 * ((i + j) % 3)});
        compareWithBruteForce(points, queries);
        const PointKdTree tree(points);
        QCOMPARE(tree.nearest(points[5]).index, std::size_t(5));
        QCOMPARE(tree.nearest(points[5], 5).index, std::size_t(5 + 144)); // its copy, at distance 0
        QCOMPARE(tree.nearest(points[5], 5).distanceSquared, 0.0);
    }

    void nonFinitePointsAreNeverReturned()
    {
        std::mt19937 random(11);
        std::vector<glm::dvec3> points = randomPoints(random, 200, 1.0);
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const double inf = std::numeric_limits<double>::infinity();
        points[3] = {nan, 0.0, 0.0};
        points[50] = {0.0, inf, 0.0};
        points[120] = {0.0, 0.0, -inf};
        const PointKdTree tree(points);
        QCOMPARE(tree.size(), points.size() - 3);
        compareWithBruteForce(points, randomPoints(random, 100, 1.5));
        QCOMPARE(tree.nearest({nan, 0.0, 0.0}).index, kNone);
        QCOMPARE(tree.nearest({0.0, inf, 0.0}).index, kNone);
    }

    void smallTrees()
    {
        const glm::dvec3 query(0.3, 0.2, 0.1);
        QCOMPARE(PointKdTree({}).nearest(query).index, kNone);
        const PointKdTree one({{1.0, 2.0, 3.0}});
        QCOMPARE(one.nearest(query).index, std::size_t(0));
        QCOMPARE(one.nearest(query, 0).index, kNone);
        QCOMPARE(one.point(0), glm::dvec3(1.0, 2.0, 3.0));
        const PointKdTree two({{1.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}});
        QCOMPARE(two.nearest({-0.5, 0.0, 0.0}).index, std::size_t(1));
        QCOMPARE(two.nearest({-0.5, 0.0, 0.0}, 1).index, std::size_t(0));
        QCOMPARE(two.nearest({-0.5, 0.0, 0.0}, 1).distanceSquared, 2.25);
    }
};

QTEST_APPLESS_MAIN(TestPointKdTree)
#include "tst_point_kd_tree.moc"
