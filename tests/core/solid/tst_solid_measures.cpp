// What Mesh Statistics measures (core/solid/solid_measures.h, self_intersections.h): the
// surface area, the cross-section in a plane (Green's theorem over the crossing
// segments, the same whichever side the plane keeps, sections of a self-crossing mesh
// added with their windings), the trimmed solid's volume, area and section, and the
// count of triangle pairs that cross.
#include "core/scene/shape_generators.h"
#include "core/solid/self_intersections.h"
#include "core/solid/solid_measures.h"

#include <glm/gtc/constants.hpp>

#include <QtTest>

#include <stop_token>

using namespace trimlab;

namespace {

TriangleMesh unitCube()
{
    return makeBox(glm::dvec3(0.0), glm::dvec3(1.0));
}

// Two unit cubes in one mesh, the second moved by +0.5 in x: they overlap in half a cube.
TriangleMesh overlappingCubes()
{
    TriangleMesh mesh = unitCube();
    appendMesh(mesh, makeBox(glm::dvec3(0.5, 0.0, 0.0), glm::dvec3(1.5, 1.0, 1.0)));
    return mesh;
}

ClipPlane plane(const glm::dvec3& normal, double offset)
{
    return ClipPlane{true, normal, offset};
}

bool near(double value, double expected, double tolerance)
{
    return std::abs(value - expected) <= tolerance;
}

} // namespace

class TestSolidMeasures : public QObject {
    Q_OBJECT
private slots:
    void surfaceAreaOfACubeAndASphere();
    void crossSectionsOfACube();
    void crossSectionOfASphere();
    void crossSectionsOfACrossingMeshAddUp();
    void trimmedSolidMeasures();
    void selfIntersectionsCountCrossingPairs();
};

void TestSolidMeasures::surfaceAreaOfACubeAndASphere()
{
    QCOMPARE(surfaceArea(unitCube()), 6.0);
    const double sphere = surfaceArea(makeIcosphere(glm::dvec3(0.0), 1.0, 4));
    QVERIFY2(near(sphere, 4.0 * glm::pi<double>(), 0.01 * 4.0 * glm::pi<double>()),
             qPrintable(QString::number(sphere)));
}

// Across the middle, at a face (its vertices count as on the positive side, so z = 1
// meets the side walls just below), turned, and obliquely through the centre: a √2 × 1
// rectangle. The side the plane keeps does not change the area.
void TestSolidMeasures::crossSectionsOfACube()
{
    const TriangleMesh cube = unitCube();
    QVERIFY(near(crossSectionArea(cube, plane({0, 0, 1}, -0.5)), 1.0, 1e-12));
    QVERIFY(near(crossSectionArea(cube, plane({0, 0, -1}, 0.5)), 1.0, 1e-12));
    QVERIFY(near(crossSectionArea(cube, plane({0, 0, 2}, -1.0)), 1.0, 1e-12)); // normal of length 2
    QVERIFY(near(crossSectionArea(cube, plane({0, 0, 1}, -1.0)), 1.0, 1e-12));
    QCOMPARE(crossSectionArea(cube, plane({0, 0, 1}, -2.0)), 0.0);
    const double oblique = crossSectionArea(cube, plane({1, 1, 0}, -1.0));
    QVERIFY2(near(oblique, std::sqrt(2.0), 1e-12), qPrintable(QString::number(oblique, 'g', 17)));
}

void TestSolidMeasures::crossSectionOfASphere()
{
    const TriangleMesh sphere = makeIcosphere(glm::dvec3(0.0), 1.0, 5);
    const double area = crossSectionArea(sphere, plane({0, 0, 1}, -0.3));
    const double exact = glm::pi<double>() * (1.0 - 0.09);
    QVERIFY2(near(area, exact, 0.005 * exact), qPrintable(QStringLiteral("%1 vs %2").arg(area).arg(exact)));
}

// The plane z = 0.5 cuts both cubes: the sections add (the half where they overlap twice),
// as the mesh's winding numbers do.
void TestSolidMeasures::crossSectionsOfACrossingMeshAddUp()
{
    QVERIFY(near(crossSectionArea(overlappingCubes(), plane({0, 0, 1}, -0.5)), 2.0, 1e-12));
}

// Under the nonzero rule the two cubes are their union, a 1.5 × 1 × 1 box: volume 1.5,
// area 8, section 1.5 in the enabled plane (and none for a disabled one).
void TestSolidMeasures::trimmedSolidMeasures()
{
    Scene scene;
    scene.objects.push_back({"cubes", overlappingCubes(), glm::dmat4(1.0)});
    TrimSettings settings;
    settings.rule = StaticRule::Nonzero;
    settings.clip = plane({0, 0, -1}, 0.5);
    const SolidMeasures measures = measureTrimmedSolid(scene, settings);
    QVERIFY2(near(measures.volume, 1.5, 1e-6), qPrintable(QString::number(measures.volume, 'g', 17)));
    QVERIFY2(near(measures.area, 8.0, 1e-6), qPrintable(QString::number(measures.area, 'g', 17)));
    QCOMPARE(measures.sections.size(), std::size_t(1));
    QCOMPARE(measures.sections.front().plane, 0);
    QVERIFY2(near(measures.sections.front().area, 1.5, 1e-6),
             qPrintable(QString::number(measures.sections.front().area, 'g', 17)));
    settings.clip.enabled = false;
    QVERIFY(measureTrimmedSolid(scene, settings).sections.empty());
}

// A cube alone does not cross itself (its neighbours share vertices); two overlapping
// cubes cross where the walls of one pass through the other: the four walls of each that
// cut the other's x = const walls, in triangles of both cubes. Moved apart, none.
void TestSolidMeasures::selfIntersectionsCountCrossingPairs()
{
    QCOMPARE(selfIntersections(unitCube()).pairs, std::size_t(0));
    const SelfIntersections crossing = selfIntersections(overlappingCubes());
    QVERIFY2(crossing.pairs >= 8, qPrintable(QString::number(crossing.pairs)));
    QVERIFY(crossing.triangles >= 8 && crossing.triangles <= 24);
    TriangleMesh apart = unitCube();
    appendMesh(apart, makeBox(glm::dvec3(2.0, 0.0, 0.0), glm::dvec3(3.0, 1.0, 1.0)));
    QCOMPARE(selfIntersections(apart).pairs, std::size_t(0));
    std::stop_source stop;
    stop.request_stop();
    QVERIFY_THROWS_EXCEPTION(OperationCancelled,
                             (void)selfIntersections(overlappingCubes(), TaskControl{{}, stop.get_token()}));
}

QTEST_APPLESS_MAIN(TestSolidMeasures)
#include "tst_solid_measures.moc"
