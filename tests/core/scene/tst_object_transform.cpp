// The Scene panel's object transform: which matrix a translation, three angles and a
// uniform scale mean (checked on points worked out by hand), that it never mirrors, and
// that decomposing a matrix gives a transform rebuilding it — or nothing for matrices no
// such transform can express.
#include "core/scene/object_transform.h"
#include "core/scene/world_geometry.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include <QtTest>

#include <cmath>
#include <limits>

using namespace trimlab;

namespace {

glm::dvec3 apply(const glm::dmat4& m, const glm::dvec3& p)
{
    const glm::dvec4 w = m * glm::dvec4(p, 1.0);
    return glm::dvec3(w);
}

bool near(const glm::dvec3& a, const glm::dvec3& b, double tolerance = 1e-12)
{
    return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::dvec3(tolerance)));
}

double largestDifference(const glm::dmat4& a, const glm::dmat4& b)
{
    double largest = 0.0;
    for (int c = 0; c < 4; ++c)
        for (int j = 0; j < 4; ++j)
            largest = std::max(largest, std::abs(a[c][j] - b[c][j]));
    return largest;
}

} // namespace

class TestObjectTransform : public QObject {
    Q_OBJECT
private slots:
    void defaultIsIdentity();
    void pointsMoveAsDocumented();
    void scaleNeverMirrorsOrCollapses();
    void nonFiniteComponentsCountAsZero();
    void decomposeRebuildsTheMatrix();
    void decomposeKeepsAnglesInRange();
    void decomposeRejectsWhatNoTransformExpresses();
    void placementsBeyondSinglePrecisionAreNamed();
    void fitIntoCubeCentresAndScalesUniformly();
};

// A transform finite in double precision can still overflow the floats that the GPU,
// every export and every file format hold: such a placement is named, not drawn as
// infinity.
void TestObjectTransform::placementsBeyondSinglePrecisionAreNamed()
{
    SceneObject object;
    object.name = "box";
    object.mesh.positions = {{-1, -1, -1}, {1, 1, 1}, {1, -1, 1}};
    object.mesh.triangles = {{0, 1, 2}};
    QCOMPARE(placementProblem(object), std::string());
    ObjectTransform far;
    far.translation = {0.0, -1e39, 0.0};
    object.modelMatrix = far.modelMatrix();
    QCOMPARE(placementProblem(object),
             std::string("its model matrix entry [3][1] is -1e+39, beyond single precision (±3.4e+38)"));
    ObjectTransform huge;
    huge.scale = 3e38; // the matrix fits in floats, the box corner at 1 does not once moved
    huge.translation = {1e38, 0.0, 0.0};
    object.modelMatrix = huge.modelMatrix();
    QCOMPARE(placementProblem(object),
             std::string("it places a vertex at x = 4e+38, beyond single precision (±3.4e+38)"));
    // Large but representable placements are fine.
    ObjectTransform large;
    large.translation = {1e30, 0.0, 0.0};
    object.modelMatrix = large.modelMatrix();
    QCOMPARE(placementProblem(object), std::string());
}

void TestObjectTransform::defaultIsIdentity()
{
    const ObjectTransform transform;
    QVERIFY(transform.isIdentity());
    QCOMPARE(transform.modelMatrix(), glm::dmat4(1.0));
    const std::optional<ObjectTransform> decomposed = decomposeObjectTransform(glm::dmat4(1.0));
    QVERIFY(decomposed);
    QVERIFY(decomposed->isIdentity());
}

// Scale about the origin, then x, y, z rotations in that order, then the translation.
void TestObjectTransform::pointsMoveAsDocumented()
{
    ObjectTransform zOnly;
    zOnly.rotationDegrees = {0.0, 0.0, 90.0};
    QVERIFY(near(apply(zOnly.modelMatrix(), {1.0, 0.0, 0.0}), {0.0, 1.0, 0.0})); // counter-clockwise about +z

    ObjectTransform yOnly;
    yOnly.rotationDegrees = {0.0, 90.0, 0.0};
    QVERIFY(near(apply(yOnly.modelMatrix(), {0.0, 0.0, 1.0}), {1.0, 0.0, 0.0})); // z -> x about +y

    // (0, 1, 0): scale 2 -> (0, 2, 0); x by 90 -> (0, 0, 2); z by 90 leaves it -> (0, 0, 2);
    // translate -> (1, 2, 5). (1, 0, 0): -> (2, 0, 0) -> (2, 0, 0) -> (0, 2, 0) -> (1, 4, 3).
    ObjectTransform all;
    all.translation = {1.0, 2.0, 3.0};
    all.rotationDegrees = {90.0, 0.0, 90.0};
    all.scale = 2.0;
    const glm::dmat4 model = all.modelMatrix();
    QVERIFY(near(apply(model, {0.0, 1.0, 0.0}), {1.0, 2.0, 5.0}));
    QVERIFY(near(apply(model, {1.0, 0.0, 0.0}), {1.0, 4.0, 3.0}));
    QVERIFY(near(apply(model, {0.0, 0.0, 0.0}), {1.0, 2.0, 3.0}));
    QCOMPARE(model[0][3], 0.0); // affine: last row (0, 0, 0, 1)
    QCOMPARE(model[3][3], 1.0);
}

void TestObjectTransform::scaleNeverMirrorsOrCollapses()
{
    for (const double scale :
         {0.0, -2.0, -1e-300, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        ObjectTransform transform;
        transform.scale = scale;
        transform.rotationDegrees = {30.0, -40.0, 50.0};
        const double determinant = glm::determinant(glm::dmat3(transform.modelMatrix()));
        QVERIFY2(determinant > 0.0 && std::isfinite(determinant), qPrintable(QString::number(scale)));
    }
}

void TestObjectTransform::nonFiniteComponentsCountAsZero()
{
    ObjectTransform transform;
    transform.translation = {std::numeric_limits<double>::quiet_NaN(), 1.0, 0.0};
    transform.rotationDegrees = {0.0, std::numeric_limits<double>::infinity(), 0.0};
    const glm::dmat4 model = transform.modelMatrix();
    QVERIFY(near(apply(model, {1.0, 0.0, 0.0}), {1.0, 1.0, 0.0}));
}

void TestObjectTransform::decomposeRebuildsTheMatrix()
{
    int checked = 0;
    for (double x = -180.0; x <= 180.0; x += 45.0)
        for (double y = -90.0; y <= 90.0; y += 30.0)
            for (double z = -135.0; z <= 180.0; z += 45.0) {
                ObjectTransform transform;
                transform.translation = {0.5, -2.0, 7.25};
                transform.rotationDegrees = {x, y, z};
                transform.scale = 0.75;
                const glm::dmat4 model = transform.modelMatrix();
                const std::optional<ObjectTransform> decomposed = decomposeObjectTransform(model);
                QVERIFY2(decomposed, qPrintable(QStringLiteral("%1 %2 %3").arg(x).arg(y).arg(z)));
                QVERIFY(largestDifference(decomposed->modelMatrix(), model) < 1e-12);
                QVERIFY(std::abs(decomposed->scale - 0.75) < 1e-12);
                QVERIFY(near(decomposed->translation, transform.translation));
                ++checked;
            }
    QCOMPARE(checked, 9 * 7 * 8);
    // A matrix not made by modelMatrix(): glm's own rotation about an oblique axis.
    const glm::dmat4 oblique = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(3.0, 0.0, -1.0)), 0.7,
                                           glm::normalize(glm::dvec3(1.0, 2.0, 3.0)));
    const std::optional<ObjectTransform> decomposed = decomposeObjectTransform(oblique);
    QVERIFY(decomposed);
    QVERIFY(largestDifference(decomposed->modelMatrix(), oblique) < 1e-12);
}

// Away from gimbal lock the angles come back as given (when given in range); at y = ±90°
// x is 0 and z carries the rotation.
void TestObjectTransform::decomposeKeepsAnglesInRange()
{
    ObjectTransform transform;
    transform.rotationDegrees = {-120.0, 35.0, 170.0};
    const std::optional<ObjectTransform> same = decomposeObjectTransform(transform.modelMatrix());
    QVERIFY(same);
    QVERIFY(near(same->rotationDegrees, transform.rotationDegrees, 1e-9));

    transform.rotationDegrees = {30.0, 90.0, 10.0};
    const std::optional<ObjectTransform> locked = decomposeObjectTransform(transform.modelMatrix());
    QVERIFY(locked);
    QCOMPARE(locked->rotationDegrees.x, 0.0);
    QVERIFY(std::abs(locked->rotationDegrees.y - 90.0) < 1e-6);
    QVERIFY(largestDifference(locked->modelMatrix(), transform.modelMatrix()) < 1e-12);

    transform.rotationDegrees = {0.0, 0.0, 200.0}; // out of range: comes back as −160
    const std::optional<ObjectTransform> wrapped = decomposeObjectTransform(transform.modelMatrix());
    QVERIFY(wrapped);
    QVERIFY(std::abs(wrapped->rotationDegrees.z + 160.0) < 1e-9);
}

void TestObjectTransform::decomposeRejectsWhatNoTransformExpresses()
{
    QVERIFY(!decomposeObjectTransform(glm::scale(glm::dmat4(1.0), glm::dvec3(-1.0, 1.0, 1.0)))); // mirror
    QVERIFY(!decomposeObjectTransform(glm::scale(glm::dmat4(1.0), glm::dvec3(1.0, 2.0, 1.0))));  // non-uniform
    QVERIFY(!decomposeObjectTransform(glm::scale(glm::dmat4(1.0), glm::dvec3(0.0))));            // collapse
    glm::dmat4 shear(1.0);
    shear[1][0] = 0.5;
    QVERIFY(!decomposeObjectTransform(shear));
    glm::dmat4 projective(1.0);
    projective[2][3] = -1.0;
    QVERIFY(!decomposeObjectTransform(projective));
    glm::dmat4 nan(1.0);
    nan[3][0] = std::numeric_limits<double>::quiet_NaN();
    QVERIFY(!decomposeObjectTransform(nan));
}

// A benchmark scene's operand: its bounds' centre lands on the given point and its largest
// side gets the given size, the other sides in proportion (no stretch, no mirror).
void TestObjectTransform::fitIntoCubeCentresAndScalesUniformly()
{
    const Bounds bounds{{1.0, 2.0, 3.0}, {3.0, 6.0, 4.0}}; // sides 2, 4, 1
    const glm::dvec3 center(-5.0, 0.5, 7.0);
    const glm::dmat4 model = fitIntoCube(bounds, center, 2.0);
    QVERIFY(near(apply(model, bounds.center()), center));
    QVERIFY(near(apply(model, bounds.max), center + glm::dvec3(0.5, 1.0, 0.25)));
    QVERIFY(near(apply(model, bounds.min), center - glm::dvec3(0.5, 1.0, 0.25)));
    QVERIFY(glm::determinant(glm::dmat3(model)) > 0.0);
}

QTEST_APPLESS_MAIN(TestObjectTransform)
#include "tst_object_transform.moc"
