// The viewport's orbit camera: fit, orbit, pan and zoom as exact math, and a far plane
// that encloses the scene whatever the user does.
#include "core/view/orbit_controller.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <QtTest>

#include <array>
#include <cmath>
#include <numbers>

using namespace trimlab;

namespace {

constexpr int kWidth = 256;
constexpr int kHeight = 192;

Bounds testBounds()
{
    Bounds b;
    b.extend({-1.0, -2.0, -0.5});
    b.extend({3.0, 1.0, 0.5});
    return b;
}

/// Continuous pixel position of `p` (x right, y down, pixel centres at half-integers).
glm::dvec2 projectToPixel(const Camera& camera, const glm::dvec3& p)
{
    const glm::dvec4 clip =
        projectionMatrix(camera, double(kWidth) / kHeight) * viewMatrix(camera) * glm::dvec4(p, 1.0);
    const double x = (clip.x / clip.w * 0.5 + 0.5) * kWidth;
    const double yFromBottom = (clip.y / clip.w * 0.5 + 0.5) * kHeight;
    return {x, kHeight - yFromBottom};
}

double viewDepth(const Camera& camera, const glm::dvec3& p)
{
    return glm::dot(p - camera.eye, glm::normalize(camera.target - camera.eye));
}

std::array<glm::dvec3, 8> corners(const Bounds& b)
{
    std::array<glm::dvec3, 8> result;
    for (int i = 0; i < 8; ++i)
        result[std::size_t(i)] = {(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                                  (i & 4) ? b.max.z : b.min.z};
    return result;
}

/// The point at view depth `depth` under the continuous pixel position (x, y).
glm::dvec3 pointUnderCursor(const Camera& camera, double x, double y, double depth)
{
    const double tanHalf = std::tan(glm::radians(camera.fovyDegrees) * 0.5);
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    const double ndcX = x / kWidth * 2.0 - 1.0;
    const double ndcY = 1.0 - y / kHeight * 2.0;
    const double aspect = double(kWidth) / kHeight;
    return camera.eye + depth * (forward + right * (ndcX * tanHalf * aspect) + up * (ndcY * tanHalf));
}

bool near(const glm::dvec3& a, const glm::dvec3& b, double tolerance)
{
    return glm::length(a - b) <= tolerance;
}

bool near(const glm::dvec2& a, const glm::dvec2& b, double tolerance)
{
    return glm::length(a - b) <= tolerance;
}

OrbitController fittedController()
{
    OrbitController orbit;
    orbit.setSceneBounds(testBounds());
    orbit.fit(double(kWidth) / kHeight);
    return orbit;
}

} // namespace

class TestOrbitController : public QObject {
    Q_OBJECT
private slots:
    void fitMatchesFitCamera();
    void fitKeepingDirectionKeepsDirection();
    void setCameraRoundTrips();
    void farPlaneAlwaysEnclosesTheScene();
    void orbitKeepsTargetAndDistance();
    void pitchIsClampedShortOfThePoles();
    void dragTurnsTheSceneWithTheCursor();
    void panMovesTheGrabbedPointWithTheCursor();
    void zoomIsMultiplicativeAndNeverPassesTheTarget();
    void zoomAtKeepsThePointUnderTheCursor();
    void badInputIsIgnored();
};

// Reset view = fitCamera with its default direction, exactly (the default clip plane of
// the GUI is chosen for that view).
void TestOrbitController::fitMatchesFitCamera()
{
    const Camera expected = fitCamera(testBounds(), double(kWidth) / kHeight);
    const Camera actual = fittedController().camera();
    QVERIFY(near(actual.eye, expected.eye, 1e-9));
    QVERIFY(near(actual.target, expected.target, 1e-12));
    QVERIFY(near(actual.up, expected.up, 0.0));
    QCOMPARE(actual.fovyDegrees, expected.fovyDegrees);
    QVERIFY(std::abs(actual.zNear - expected.zNear) < 1e-9);
    QVERIFY(std::abs(actual.zFar - expected.zFar) < 1e-9);
}

void TestOrbitController::fitKeepingDirectionKeepsDirection()
{
    OrbitController orbit = fittedController();
    orbit.orbit(0.7, -0.3);
    orbit.pan(40.0, -25.0, kHeight, orbit.distance());
    orbit.zoom(0.2);
    const glm::dvec3 direction = orbit.viewDirection();
    orbit.fitKeepingDirection(double(kWidth) / kHeight);
    QVERIFY(near(orbit.viewDirection(), direction, 1e-12));
    const Camera expected = fitCamera(testBounds(), double(kWidth) / kHeight, direction);
    QVERIFY(near(orbit.camera().eye, expected.eye, 1e-9));
    QVERIFY(near(orbit.target(), testBounds().center(), 1e-12));
}

void TestOrbitController::setCameraRoundTrips()
{
    OrbitController orbit;
    orbit.setSceneBounds(testBounds());
    Camera camera;
    camera.eye = {2.0, 1.5, 4.0};
    camera.target = {0.5, -0.25, 0.0};
    camera.fovyDegrees = 30.0;
    orbit.setCamera(camera);
    const Camera result = orbit.camera();
    QVERIFY(near(result.eye, camera.eye, 1e-12));
    QVERIFY(near(result.target, camera.target, 0.0));
    QCOMPARE(result.fovyDegrees, 30.0);
    // An eye on the target is moved off it, never left degenerate.
    camera.eye = camera.target;
    orbit.setCamera(camera);
    QVERIFY(orbit.distance() >= orbit.minDistance());
    QVERIFY(glm::length(orbit.camera().eye - orbit.camera().target) > 0.0);
}

// Whatever sequence of operations the user performs, every corner of the scene box lies
// in front of the far plane and the depth range stays valid.
void TestOrbitController::farPlaneAlwaysEnclosesTheScene()
{
    OrbitController orbit = fittedController();
    const auto box = corners(testBounds());
    for (int step = 0; step < 400; ++step) {
        switch (step % 5) {
        case 0:
            orbit.orbitByDrag(37.0 * std::sin(step), 23.0 * std::cos(0.7 * step), kHeight);
            break;
        case 1:
            orbit.pan(15.0 * std::cos(step), -11.0 * std::sin(step), kHeight, orbit.distance());
            break;
        case 2:
            orbit.zoom(step % 3 == 0 ? 1.7 : 0.3);
            break;
        case 3:
            orbit.zoomAt(0.6, (step * 17) % kWidth, (step * 29) % kHeight, kWidth, kHeight);
            break;
        default:
            orbit.zoom(OrbitController::wheelZoomFactor(step % 2 == 0 ? -3.0 : 5.0));
            break;
        }
        const Camera camera = orbit.camera();
        QVERIFY(camera.zNear > 0.0);
        QVERIFY(camera.zNear < camera.zFar);
        for (const glm::dvec3& corner : box)
            QVERIFY2(viewDepth(camera, corner) < camera.zFar, qPrintable(QString("step %1").arg(step)));
    }
}

void TestOrbitController::orbitKeepsTargetAndDistance()
{
    OrbitController orbit = fittedController();
    const glm::dvec3 target = orbit.target();
    const double distance = orbit.distance();
    orbit.orbit(1.3, 0.4);
    QVERIFY(near(orbit.target(), target, 0.0));
    QCOMPARE(orbit.distance(), distance);
    QVERIFY(std::abs(glm::length(orbit.camera().eye - target) - distance) < 1e-9);
    // A full turn of yaw comes back to the same eye.
    const glm::dvec3 eye = orbit.camera().eye;
    orbit.orbit(2.0 * std::numbers::pi, 0.0);
    QVERIFY(near(orbit.camera().eye, eye, 1e-9));
}

void TestOrbitController::pitchIsClampedShortOfThePoles()
{
    OrbitController orbit = fittedController();
    const double limit = glm::radians(OrbitController::kMaxPitchDegrees);
    orbit.orbit(0.0, 10.0);
    QCOMPARE(orbit.pitchRadians(), limit);
    Camera camera = orbit.camera();
    QVERIFY(glm::length(glm::cross(camera.target - camera.eye, camera.up)) > 0.01);
    orbit.orbitByDrag(0.0, -100.0 * kHeight, kHeight);
    QCOMPARE(orbit.pitchRadians(), -limit);
    // A camera straight above the target is clamped too.
    camera.eye = camera.target + glm::dvec3(0.0, 5.0, 0.0);
    orbit.setCamera(camera);
    QCOMPARE(orbit.pitchRadians(), limit);
}

// Dragging right moves the scene's front point right; dragging down moves it down.
void TestOrbitController::dragTurnsTheSceneWithTheCursor()
{
    OrbitController orbit;
    orbit.setSceneBounds(testBounds());
    Camera start;
    start.eye = {0.0, 0.0, 10.0};
    start.target = {0.0, 0.0, 0.0};
    orbit.setCamera(start);
    const glm::dvec3 front{0.0, 0.0, 1.0};
    const glm::dvec2 before = projectToPixel(orbit.camera(), front);
    orbit.orbitByDrag(20.0, 0.0, kHeight);
    QVERIFY(projectToPixel(orbit.camera(), front).x > before.x + 1.0);
    orbit.setCamera(start);
    orbit.orbitByDrag(0.0, 20.0, kHeight);
    QVERIFY(projectToPixel(orbit.camera(), front).y > before.y + 1.0);
    // Half a viewport height of drag turns by 90°.
    orbit.setCamera(start);
    orbit.orbitByDrag(-kHeight / 2.0, 0.0, kHeight);
    QVERIFY(near(orbit.camera().eye, glm::dvec3(10.0, 0.0, 0.0), 1e-9));
}

void TestOrbitController::panMovesTheGrabbedPointWithTheCursor()
{
    for (const double depthFactor : {0.5, 1.0, 1.8}) {
        OrbitController orbit = fittedController();
        orbit.orbit(0.4, 0.2);
        const Camera camera = orbit.camera();
        const double depth = orbit.distance() * depthFactor;
        const PixelRay ray = pixelRay(camera, kWidth, kHeight, 100, 70);
        const glm::dvec3 grabbed = ray.origin + ray.direction * depth;
        const glm::dvec2 before = projectToPixel(camera, grabbed);
        QVERIFY(near(before, glm::dvec2(100.5, 70.5), 1e-9));
        orbit.pan(31.0, -12.5, kHeight, depth);
        QVERIFY(near(projectToPixel(orbit.camera(), grabbed), before + glm::dvec2(31.0, -12.5), 1e-7));
        QVERIFY(near(orbit.viewDirection(), glm::normalize(camera.target - camera.eye), 1e-12));
    }
}

void TestOrbitController::zoomIsMultiplicativeAndNeverPassesTheTarget()
{
    OrbitController orbit = fittedController();
    const double distance = orbit.distance();
    const glm::dvec3 direction = orbit.viewDirection();
    orbit.zoom(0.5);
    QVERIFY(std::abs(orbit.distance() - 0.5 * distance) < 1e-12 * distance);
    orbit.zoom(2.0);
    QVERIFY(std::abs(orbit.distance() - distance) < 1e-12 * distance);
    for (int i = 0; i < 200; ++i)
        orbit.zoom(OrbitController::wheelZoomFactor(10.0));
    QCOMPARE(orbit.distance(), orbit.minDistance());
    QVERIFY(orbit.minDistance() > 0.0);
    QVERIFY(near(orbit.viewDirection(), direction, 1e-12));
    const Camera camera = orbit.camera();
    QVERIFY(glm::dot(camera.target - camera.eye, direction) > 0.0);
    for (int i = 0; i < 200; ++i)
        orbit.zoom(OrbitController::wheelZoomFactor(-10.0));
    QCOMPARE(orbit.distance(), orbit.maxDistance());
    QVERIFY(OrbitController::wheelZoomFactor(1.0) < 1.0);
}

void TestOrbitController::zoomAtKeepsThePointUnderTheCursor()
{
    OrbitController orbit = fittedController();
    orbit.orbit(-0.3, 0.25);
    const Camera camera = orbit.camera();
    const double cursorX = 40.25, cursorY = 150.5;
    const glm::dvec3 point = pointUnderCursor(camera, cursorX, cursorY, orbit.distance());
    QVERIFY(near(projectToPixel(camera, point), glm::dvec2(cursorX, cursorY), 1e-9));
    const double distance = orbit.distance();
    orbit.zoomAt(0.25, cursorX, cursorY, kWidth, kHeight);
    QVERIFY(std::abs(orbit.distance() - 0.25 * distance) < 1e-12 * distance);
    QVERIFY(near(projectToPixel(orbit.camera(), point), glm::dvec2(cursorX, cursorY), 1e-7));
    QVERIFY(near(orbit.viewDirection(), glm::normalize(camera.target - camera.eye), 1e-12));
    // Zooming out about the same cursor point undoes it.
    orbit.zoomAt(4.0, cursorX, cursorY, kWidth, kHeight);
    QVERIFY(near(orbit.camera().eye, camera.eye, 1e-9));
}

void TestOrbitController::badInputIsIgnored()
{
    OrbitController orbit = fittedController();
    const Camera before = orbit.camera();
    orbit.zoom(0.0);
    orbit.zoom(-2.0);
    orbit.zoom(std::nan(""));
    orbit.zoomAt(0.5, 10.0, 10.0, 0, kHeight);
    orbit.pan(10.0, 10.0, kHeight, 0.0);
    orbit.pan(10.0, 10.0, 0, 1.0);
    orbit.orbit(std::nan(""), 0.1);
    orbit.orbitByDrag(10.0, 10.0, 0);
    orbit.fit(double(kWidth) / kHeight, glm::dvec3(0.0));
    const Camera after = orbit.camera();
    QVERIFY(near(after.eye, before.eye, 1e-9));
    QVERIFY(near(after.target, before.target, 1e-12));
}

QTEST_APPLESS_MAIN(TestOrbitController)
#include "tst_orbit_controller.moc"
