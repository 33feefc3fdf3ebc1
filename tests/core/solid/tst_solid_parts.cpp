// The exact steps under the trimmed solid, on boxes and single triangles: the arrangement
// of crossing triangles, the refined soup with its per-object deltas, and the winding
// numbers of its cells.
#include "core/solid/cell_windings.h"
#include "core/solid/exact_kernel.h"
#include "core/solid/refined_soup.h"
#include "core/solid/triangle_arrangement.h"

#include "core/scene/scene.h"
#include "core/scene/shape_generators.h"

#include <QtTest>

#include <cmath>
#include <stop_token>

using namespace trimlab;
using namespace trimlab::solid;

namespace {

double area(const std::array<ExactPoint, 3>& t)
{
    return std::sqrt(CGAL::to_double(ExactKernel::Triangle_3(t[0], t[1], t[2]).squared_area()));
}

Scene sceneOf(std::initializer_list<TriangleMesh> meshes)
{
    Scene scene;
    for (const TriangleMesh& mesh : meshes)
        scene.objects.push_back(SceneObject{"box", mesh, glm::dmat4(1.0)});
    return scene;
}

} // namespace

class TestSolidParts : public QObject {
    Q_OBJECT

private slots:
    // A triangle piercing another splits both; every piece lies in its source, runs the
    // same way round, and the pieces of a source tile it. Apart, nothing is split.
    void crossingTrianglesAreSplitAlongTheirIntersection()
    {
        const std::vector<std::array<ExactPoint, 3>> triangles = {
            {ExactPoint(-1, -1, 0), ExactPoint(1, -1, 0), ExactPoint(0, 1, 0)},
            {ExactPoint(0, 0, -1), ExactPoint(0, 0, 1), ExactPoint(0.2, 2, 0)}};
        const std::vector<ArrangedTriangle> pieces = arrangeTriangles(triangles, {});
        QVERIFY(pieces.size() > 2);
        double sums[2] = {0.0, 0.0};
        for (const ArrangedTriangle& piece : pieces) {
            QVERIFY(piece.source < 2);
            const auto& s = triangles[piece.source];
            const ExactKernel::Plane_3 plane(s[0], s[1], s[2]);
            for (const ExactPoint& corner : piece.corners)
                QVERIFY(plane.has_on(corner));
            const ExactVector pieceNormal =
                CGAL::cross_product(piece.corners[1] - piece.corners[0], piece.corners[2] - piece.corners[0]);
            QVERIFY(pieceNormal * plane.orthogonal_vector() > 0); // the same way round
            sums[piece.source] += area(piece.corners);
        }
        QVERIFY(std::abs(sums[0] - area(triangles[0])) < 1e-12);
        QVERIFY(std::abs(sums[1] - area(triangles[1])) < 1e-12);

        const std::vector<std::array<ExactPoint, 3>> apart = {
            triangles[0], {ExactPoint(5, 0, 0), ExactPoint(6, 0, 0), ExactPoint(5, 1, 0)}};
        QCOMPARE(arrangeTriangles(apart, {}).size(), std::size_t(2));
    }

    // A closed outward box: 12 faces, each with delta +1 (inside behind); a degenerate
    // triangle is dropped and a face paired with its reverse cancels.
    void refinedBoxesCarryTheirDeltas()
    {
        const RefinedSoup box = refineScene(sceneOf({makeBox({0, 0, 0}, {1, 1, 1})}), {});
        QCOMPARE(box.inputTriangles, std::size_t(12));
        QCOMPARE(box.faces.size(), std::size_t(12));
        QCOMPARE(box.points.size(), std::size_t(8));
        for (const RefinedFace& face : box.faces)
            QCOMPARE(face.delta, std::vector<int>{1});

        TriangleMesh extra = makeBox({0, 0, 0}, {1, 1, 1});
        extra.positions.push_back({3, 0, 0});
        extra.positions.push_back({4, 0, 0});
        extra.positions.push_back({5, 0, 0});
        extra.triangles.push_back({8, 9, 10}); // collinear: zero area
        const glm::uvec3 first = extra.triangles[0];
        extra.triangles.push_back({first.x, first.z, first.y}); // face 0 reversed
        const RefinedSoup soup = refineScene(sceneOf({extra}), {});
        QCOMPARE(soup.degenerateTriangles, std::size_t(1));
        QVERIFY(soup.cancelledFaces >= 1);
        QCOMPARE(soup.faces.size(), std::size_t(11));

        std::stop_source stop;
        stop.request_stop();
        TaskControl cancelled;
        cancelled.stop = stop.get_token();
        QVERIFY_THROWS_EXCEPTION(OperationCancelled, (void)refineScene(sceneOf({extra}), cancelled));
    }

    // Nested boxes of two objects: every face has the outside (0) in front for the outer
    // box; the inner box's faces have object 0 = 1 in front. Two disjoint boxes are two
    // components.
    void cellsGetTheirWindingNumbers()
    {
        const RefinedSoup nested =
            refineScene(sceneOf({makeBox({0, 0, 0}, {3, 3, 3}), makeBox({1, 1, 1}, {2, 2, 2})}), {});
        const CellWindings windings = cellWindings(nested, {});
        QCOMPARE(windings.contradictions, std::size_t(0));
        QCOMPARE(windings.components, std::size_t(2));
        QCOMPARE(windings.front.size(), nested.faces.size());
        for (std::size_t f = 0; f < nested.faces.size(); ++f) {
            const bool inner = nested.faces[f].delta[1] != 0;
            QCOMPARE(windings.front[f][0], inner ? 1 : 0);
            QCOMPARE(windings.front[f][1], 0);
            QCOMPARE(windings.front[f][0] + nested.faces[f].delta[0], 1); // inside the outer box behind
        }

        const RefinedSoup apart =
            refineScene(sceneOf({makeBox({0, 0, 0}, {1, 1, 1}), makeBox({5, 0, 0}, {6, 1, 1})}), {});
        QCOMPARE(cellWindings(apart, {}).components, std::size_t(2));
        const RefinedSoup one = refineScene(sceneOf({makeBox({0, 0, 0}, {1, 1, 1})}), {});
        QCOMPARE(cellWindings(one, {}).components, std::size_t(1));
    }
};

QTEST_APPLESS_MAIN(TestSolidParts)
#include "tst_solid_parts.moc"
