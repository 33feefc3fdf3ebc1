// Deformation gradients and the per-pose features (thesis 2.2.1): a rigid rotation gives
// exactly its angle, a pure or non-uniform scale gives 0, reflections and degenerate faces
// are handled, the per-vertex averages, which poses have a feature, velocity values.
#include "core/animation/deformation_gradient.h"
#include "core/animation/pose_features.h"

#include "animation_fixtures.h"

#include <QtTest>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include <cmath>

using namespace trimlab;

namespace {

const TriangleCorners kTriangle{glm::dvec3(0.3, -0.2, 0.5), glm::dvec3(1.4, 0.1, 0.2), glm::dvec3(0.1, 1.2, -0.3)};

TriangleCorners transformed(const TriangleCorners& c, const glm::dmat4& m)
{
    TriangleCorners out;
    for (int i = 0; i < 3; ++i)
        out[std::size_t(i)] = glm::dvec3(m * glm::dvec4(c[std::size_t(i)], 1.0));
    return out;
}

double angleBetween(const TriangleCorners& a, const TriangleCorners& b)
{
    const std::optional<glm::dmat3> x = deformationGradient(a, b);
    return x ? rotationAngle(polarRotation(*x)) : std::nan("");
}

} // namespace

class TestAnimationFeatures : public QObject {
    Q_OBJECT
private slots:
    void fourthVertexAlongNormal();
    void rigidRotationGivesItsAngle_data();
    void rigidRotationGivesItsAngle();
    void scalesGiveZero();
    void reflectionBecomesRotation();
    void degenerateFacesAreSkipped();
    void faceAnglesFromFloatPositions();
    void vertexAveraging();
    void featurePosesPerKind();
    void affectedByEdit();
    void velocityAndAcceleration();
};

// Legs of length 2 along x and y: cross = (0,0,4), v4 = v1 + (0,0,4)/√4 = v1 + (0,0,2).
void TestAnimationFeatures::fourthVertexAlongNormal()
{
    const TriangleCorners right{glm::dvec3(1, 1, 1), glm::dvec3(3, 1, 1), glm::dvec3(1, 3, 1)};
    QCOMPARE(trimlab::fourthVertex(right), glm::dvec3(1, 1, 3));
    const TriangleCorners flat{glm::dvec3(0), glm::dvec3(1, 0, 0), glm::dvec3(2, 0, 0)};
    QCOMPARE(trimlab::fourthVertex(flat), glm::dvec3(0));
}

void TestAnimationFeatures::rigidRotationGivesItsAngle_data()
{
    QTest::addColumn<double>("angle");
    QTest::addColumn<double>("ax");
    QTest::addColumn<double>("ay");
    QTest::addColumn<double>("az");
    QTest::newRow("0.7 rad about z") << 0.7 << 0.0 << 0.0 << 1.0;
    QTest::newRow("0.7 rad oblique") << 0.7 << 1.0 << -2.0 << 0.5;
    QTest::newRow("1e-4 rad") << 1e-4 << 0.3 << 0.4 << 0.5;
    QTest::newRow("90 degrees") << M_PI / 2 << 1.0 << 1.0 << 1.0;
    QTest::newRow("3.1 rad") << 3.1 << -0.2 << 1.0 << 0.1;
}

// X = R exactly for a rotation + translation; the angle comes back to double precision.
void TestAnimationFeatures::rigidRotationGivesItsAngle()
{
    QFETCH(double, angle);
    QFETCH(double, ax);
    QFETCH(double, ay);
    QFETCH(double, az);
    const glm::dmat4 motion =
        glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(4, -1, 2)), angle, glm::dvec3(ax, ay, az));
    const double measured = angleBetween(kTriangle, transformed(kTriangle, motion));
    QVERIFY2(std::abs(measured - angle) < 1e-12, qPrintable(QString::number(measured, 'g', 17)));
    // Either direction of the map gives the same angle (eq. 2.2 maps pose → reference).
    QVERIFY(std::abs(angleBetween(transformed(kTriangle, motion), kTriangle) - angle) < 1e-12);
}

void TestAnimationFeatures::scalesGiveZero()
{
    const glm::dmat4 uniform = glm::scale(glm::dmat4(1.0), glm::dvec3(2.5));
    QVERIFY(angleBetween(kTriangle, transformed(kTriangle, uniform)) < 1e-12);
    // A stretch along x of a triangle in the z = 0 plane: X = diag(3, 1, √3), symmetric.
    const TriangleCorners planar{glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(0.2, 1, 0)};
    const glm::dmat4 stretch = glm::scale(glm::dmat4(1.0), glm::dvec3(3, 1, 1));
    QVERIFY(angleBetween(planar, transformed(planar, stretch)) < 1e-12);
    QVERIFY(angleBetween(kTriangle, kTriangle) < 1e-12);
}

// A mirror matrix has det −1; its closest proper rotation is orthonormal with det +1.
void TestAnimationFeatures::reflectionBecomesRotation()
{
    const glm::dmat3 mirror(glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, -1));
    const glm::dmat3 r = polarRotation(mirror);
    QVERIFY(std::abs(glm::determinant(r) - 1.0) < 1e-12);
    const glm::dmat3 identity = glm::transpose(r) * r;
    for (int c = 0; c < 3; ++c)
        for (int row = 0; row < 3; ++row)
            QVERIFY(std::abs(identity[c][row] - (c == row ? 1.0 : 0.0)) < 1e-12);
    // Rotation by 30° composed with a mirror: the rotation part still has det +1.
    const glm::dmat3 rotated = glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.5, glm::dvec3(0, 0, 1))) * mirror;
    QVERIFY(std::abs(glm::determinant(polarRotation(rotated)) - 1.0) < 1e-12);
}

void TestAnimationFeatures::degenerateFacesAreSkipped()
{
    const TriangleCorners collinear{glm::dvec3(0), glm::dvec3(1, 0, 0), glm::dvec3(2, 0, 0)};
    QVERIFY(!deformationGradient(collinear, kTriangle));
    QVERIFY(!deformationGradient(kTriangle, collinear));
    const TriangleCorners sliver{glm::dvec3(0), glm::dvec3(1, 0, 0), glm::dvec3(2, 1e-12, 0)};
    QVERIFY(!deformationGradient(kTriangle, sliver));
    const TriangleCorners nan{glm::dvec3(std::nan("")), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0)};
    QVERIFY(!deformationGradient(nan, kTriangle));
}

// The strip's right half (x ≥ 2) turned in its plane by 0.5 rad about the z axis through
// (2, 0, 0), from float positions: quads 2 and 3 (x in [2, 4]) move rigidly and turn by
// 0.5, quad 0 stays, quad 1 is sheared (not checked).
void TestAnimationFeatures::faceAnglesFromFloatPositions()
{
    const TriangleMesh strip = test::stripMesh(5);
    std::vector<glm::vec3> pose = strip.positions;
    const glm::dmat4 turn =
        glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(2, 0, 0)), 0.5, glm::dvec3(0, 0, 1)) *
        glm::translate(glm::dmat4(1.0), glm::dvec3(-2, 0, 0));
    for (glm::vec3& p : pose)
        if (p.x >= 2.0f)
            p = glm::vec3(turn * glm::dvec4(glm::dvec3(p), 1.0));
    const std::vector<double> angles = faceRotationAngles(strip.positions, pose, strip.triangles);
    QCOMPARE(angles.size(), std::size_t(8));
    for (const std::size_t f : {0, 1})
        QVERIFY2(std::abs(angles[f]) < 1e-6, qPrintable(QString::number(angles[f])));
    for (const std::size_t f : {4, 5, 6, 7})
        QVERIFY2(std::abs(angles[f] - 0.5) < 1e-6, qPrintable(QString::number(angles[f])));
}

// Face angles a = 0.2 (area 1) and b = 0.6 (area 3) around vertex 0: uniform (a + b)/2 =
// 0.4, area-weighted (1·a + 3·b)/4 = 0.5. A NaN face is ignored; a lone vertex gets 0.
void TestAnimationFeatures::vertexAveraging()
{
    const std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {-3, 0, 0}, {0, -2, 0}, {5, 5, 5}};
    const std::vector<glm::uvec3> triangles = {{0, 1, 2}, {0, 3, 4}, {0, 2, 3}};
    const std::vector<double> faces = {0.2, 0.6, std::nan("")};
    const std::vector<double> uniform = vertexRotationAngles(faces, triangles, positions, 6, VertexAveraging::Uniform);
    const std::vector<double> weighted =
        vertexRotationAngles(faces, triangles, positions, 6, VertexAveraging::AreaWeighted);
    QVERIFY(std::abs(uniform[0] - 0.4) < 1e-15);
    QVERIFY(std::abs(weighted[0] - 0.5) < 1e-15);
    QCOMPARE(uniform[1], 0.2);
    QCOMPARE(uniform[5], 0.0);
}

void TestAnimationFeatures::featurePosesPerKind()
{
    FeatureSettings s;
    QCOMPARE(featurePoses(5, 2, s), (std::vector<std::size_t>{0, 1, 3, 4}));
    s.reference = ReferenceMode::Previous;
    QCOMPARE(featurePoses(5, 2, s), (std::vector<std::size_t>{1, 2, 3, 4}));
    s.kind = FeatureKind::Velocity;
    QCOMPARE(featurePoses(5, 2, s), (std::vector<std::size_t>{1, 2, 3, 4}));
    s.kind = FeatureKind::Acceleration;
    QCOMPARE(featurePoses(5, 2, s), (std::vector<std::size_t>{1, 2, 3}));
    QCOMPARE(featurePoses(2, 0, s), std::vector<std::size_t>{});
}

void TestAnimationFeatures::affectedByEdit()
{
    FeatureSettings s;
    QCOMPARE(posesAffectedByEdit(6, 0, 3, s), (std::vector<std::size_t>{3}));
    QCOMPARE(posesAffectedByEdit(6, 0, 0, s), (std::vector<std::size_t>{1, 2, 3, 4, 5}));
    s.reference = ReferenceMode::Previous;
    QCOMPARE(posesAffectedByEdit(6, 0, 3, s), (std::vector<std::size_t>{3, 4}));
    QCOMPARE(posesAffectedByEdit(6, 0, 5, s), (std::vector<std::size_t>{5}));
    s.kind = FeatureKind::Acceleration;
    QCOMPARE(posesAffectedByEdit(6, 0, 3, s), (std::vector<std::size_t>{2, 3, 4}));
}

// Vertex 3 of a 3-pose strip moves (3,0,0) → (3,0,1) → (3,0,3): velocity at pose 1 is
// (0,0,1), at pose 2 (0,0,2); acceleration at pose 1 is (0,0,3) − 2·(0,0,1) + 0 = (0,0,1).
void TestAnimationFeatures::velocityAndAcceleration()
{
    const TriangleMesh strip = test::stripMesh(5);
    std::vector<glm::vec3> p1 = strip.positions;
    std::vector<glm::vec3> p2 = strip.positions;
    p1[3].z = 1.0f;
    p2[3].z = 3.0f;
    const MeshAnimation a = test::animationOf(strip, {p1, p2});
    FeatureSettings s;
    s.kind = FeatureKind::Velocity;
    const PoseFeature v2 = computePoseFeature(a, 2, s);
    QCOMPARE(v2.dimension, std::size_t(3));
    QCOMPARE(v2.values[3 * 3 + 2], 2.0);
    QCOMPARE(v2.values[4 * 3 + 2], 0.0);
    s.kind = FeatureKind::Acceleration;
    QCOMPARE(computePoseFeature(a, 1, s).values[3 * 3 + 2], 1.0);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)computePoseFeature(a, 2, s));
}

QTEST_GUILESS_MAIN(TestAnimationFeatures)
#include "tst_animation_features.moc"
