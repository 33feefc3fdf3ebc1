// The pieces under the editable surfaces: NURBS sample parameters, the cage's faces and
// the order of its checks, and the stencil rows and tables of the subdivision build.
#include "core/surface/nurbs_sampling.h"
#include "core/surface/subdivision_cage.h"
#include "core/surface/subdivision_refinement.h"

#include "core/surface/subdivision_cages.h"

#include <QtTest>

#include <functional>
#include <string>

using namespace trimlab;

namespace {

std::string cageProblem(const SubdivisionCage& cage)
{
    try {
        validateCage(cage);
    } catch (const SubdivisionError& e) {
        return e.what();
    }
    return "";
}

} // namespace

class TestSurfaceParts : public QObject {
    Q_OBJECT

private slots:
    // Every distinct knot is a sample; spans are split by their share of the domain; a
    // closed direction has at least three intervals.
    void tessellationParametersFollowTheKnots()
    {
        QCOMPARE(tessellationParameters({0, 0, 0, 1, 3, 3, 3}, 6, false),
                 (std::vector<double>{0, 0.5, 1, 1.5, 2, 2.5, 3}));
        QCOMPARE(tessellationParameters({0, 0, 0, 1, 3, 3, 3}, 1, false), (std::vector<double>{0, 1, 3}));
        QCOMPARE(tessellationParameters({0, 0, 1, 1}, 1, true), (std::vector<double>{0, 1.0 / 3.0, 2.0 / 3.0, 1}));
        QCOMPARE(tessellationParameters({0, 0, 1, 1}, 4, false), (std::vector<double>{0, 0.25, 0.5, 0.75, 1}));
    }

    void cageFacesAndChecks()
    {
        SubdivisionCage cage = cubeCage(1.0);
        QCOMPARE(cageProblem(cage), std::string());
        QCOMPARE(cage.faceStart(2), std::size_t(8));
        QCOMPARE(cage.face(2).size(), std::size_t(4));
        QCOMPARE(cage.face(2)[0], cage.faceIndices[8]);

        SubdivisionCage repeated = cage;
        repeated.faceIndices[1] = repeated.faceIndices[0];
        QVERIFY2(cageProblem(repeated).find("cage face 0 repeats vertex") != std::string::npos,
                 cageProblem(repeated).c_str());
        try {
            validateCage(repeated);
        } catch (const SubdivisionError& e) {
            QVERIFY(e.element() && e.element()->kind == CageElement::Kind::Face && e.element()->index == 0);
        }
        SubdivisionCage loop = cage;
        loop.scheme = SubdivisionScheme::Loop;
        QVERIFY(cageProblem(loop).find("Loop subdivision needs triangles") != std::string::npos);
        SubdivisionCage both = repeated; // a repeated vertex is found before the Loop rule
        both.scheme = SubdivisionScheme::Loop;
        QVERIFY(cageProblem(both).find("repeats vertex") != std::string::npos);
        SubdivisionCage unused = cage;
        unused.positions.emplace_back(9, 9, 9);
        QVERIFY(!cageProblem(unused).empty());
        SubdivisionCage crease = cage;
        crease.creases.push_back({cage.face(0)[0], cage.face(0)[2], kInfiniteSharpness}); // a diagonal
        QVERIFY(!cageProblem(crease).empty());
        crease.creases.back() = {cage.face(0)[0], cage.face(0)[1], -1.0f};
        QVERIFY(!cageProblem(crease).empty());
        QVERIFY(!cageProblem(SubdivisionCage{}).empty());
    }

    void stencilRowsAreSortedMergedAndSparse()
    {
        SubdivisionSurface::StencilRows rows;
        std::vector<StencilWeight> row = {{5, 0.25}, {2, 0.5}, {5, 0.25}, {9, 0.0}, {3, 1.0}, {3, -1.0}};
        appendStencilRow(rows, row);
        QCOMPARE(rows.offsets, (std::vector<std::size_t>{0, 2}));
        QCOMPARE(rows.entries.size(), std::size_t(2));
        QCOMPARE(rows.entries[0].cageVertex, std::uint32_t(2));
        QCOMPARE(rows.entries[0].weight, 0.5);
        QCOMPARE(rows.entries[1].cageVertex, std::uint32_t(5));
        QCOMPARE(rows.entries[1].weight, 0.5);
        std::vector<StencilWeight> empty;
        appendStencilRow(rows, empty);
        QCOMPARE(rows.offsets, (std::vector<std::size_t>{0, 2, 2}));
    }

    // The cube's quads split into triangles at level 0 and into 4^level quads each after;
    // the built tables hold what was predicted, every row a partition of unity.
    void tablesHoldThePredictedTriangles()
    {
        const SubdivisionCage cube = cubeCage(1.0);
        QCOMPARE(predictedTriangleCount(cube, 0), std::size_t(12));
        QCOMPARE(predictedTriangleCount(cube, 2), std::size_t(6 * 16 * 2));
        for (const int level : {0, 1, 2}) {
            const SubdivisionTables tables = buildSubdivisionTables(cube, {level, SubdivisionMode::Uniform});
            QCOMPARE(tables.triangles.size(), predictedTriangleCount(cube, level));
            QCOMPARE(tables.position.offsets.size(), tables.outputVertexCount + 1);
            for (std::size_t v = 0; v < tables.outputVertexCount; ++v) {
                double sum = 0.0;
                for (std::size_t e = tables.position.offsets[v]; e < tables.position.offsets[v + 1]; ++e)
                    sum += tables.position.entries[e].weight;
                QVERIFY(std::abs(sum - 1.0) < 1e-12);
            }
            QVERIFY(tables.locations.empty());
        }
        QCOMPARE(buildSubdivisionTables(cube, {1, SubdivisionMode::Uniform}).outputVertexCount, std::size_t(26));
        const SubdivisionTables limit = buildSubdivisionTables(cube, {1, SubdivisionMode::Limit});
        QCOMPARE(limit.locations.size(), limit.outputVertexCount);
        QCOMPARE(limit.tangentU.offsets.size(), limit.outputVertexCount + 1);
    }
};

QTEST_APPLESS_MAIN(TestSurfaceParts)
#include "tst_surface_parts.moc"
