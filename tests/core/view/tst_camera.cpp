// Camera conventions the GPU and the CPU reference both rely on.
#include "core/trim/clip_plane.h"
#include "core/view/camera.h"

#include <glm/geometric.hpp>

#include <QtTest>

using namespace trimlab;

class TestCamera : public QObject {
    Q_OBJECT
private slots:
    void pixelRayMatchesProjection();
    void rayParameterIsViewDepth();
    void fitEnclosesBoundsWithFarBeyond();
    void parseCameraRejectsBadInput();
    void keptSpanCases();
};

// Projecting a point on a pixel's ray with the GL matrices lands on that pixel's centre.
void TestCamera::pixelRayMatchesProjection()
{
    Camera c;
    c.eye = {1.0, 2.0, 5.0};
    c.target = {0.2, -0.1, 0.3};
    c.fovyDegrees = 50.0;
    c.zNear = 0.1;
    c.zFar = 50.0;
    const int w = 64, h = 48;
    const glm::dmat4 vp = projectionMatrix(c, double(w) / h) * viewMatrix(c);
    for (auto [x, y] : {std::pair{0, 0}, {63, 47}, {17, 30}, {32, 24}}) {
        const PixelRay ray = pixelRay(c, w, h, x, y);
        const glm::dvec4 clip = vp * glm::dvec4(ray.origin + 3.0 * ray.direction, 1.0);
        const double px = (clip.x / clip.w * 0.5 + 0.5) * w;
        const double pyFromBottom = (clip.y / clip.w * 0.5 + 0.5) * h;
        QVERIFY(std::abs(px - (x + 0.5)) < 1e-9);
        QVERIFY(std::abs((h - pyFromBottom) - (y + 0.5)) < 1e-9);
    }
}

void TestCamera::rayParameterIsViewDepth()
{
    Camera c;
    c.eye = {0.5, -1.0, 4.0};
    c.target = {0.0, 0.0, 0.0};
    const PixelRay ray = pixelRay(c, 100, 80, 7, 66);
    const glm::dvec4 view = viewMatrix(c) * glm::dvec4(ray.origin + 2.5 * ray.direction, 1.0);
    QVERIFY(std::abs(-view.z - 2.5) < 1e-12);
}

void TestCamera::fitEnclosesBoundsWithFarBeyond()
{
    Bounds b;
    b.extend({-1.0, -2.0, -0.5});
    b.extend({3.0, 1.0, 0.5});
    const Camera c = fitCamera(b, 4.0 / 3.0);
    const glm::dvec3 forward = glm::normalize(c.target - c.eye);
    const double centerDepth = glm::dot(b.center() - c.eye, forward);
    QVERIFY(c.zFar > centerDepth + b.radius());
    QVERIFY(c.zNear > 0.0 && c.zNear < centerDepth - b.radius());
    // Eye inside the bounds: the near plane stays small, the far plane beyond.
    Camera inside = c;
    inside.eye = b.center();
    inside.target = b.center() + glm::dvec3(0, 0, -1);
    inside = withDepthRange(inside, b);
    QVERIFY(inside.zNear <= 1e-3 * b.radius() * 1.0001);
    QVERIFY(inside.zFar > b.radius());
}

void TestCamera::parseCameraRejectsBadInput()
{
    std::string error;
    QVERIFY(parseCamera("0,0,3,0,0,0,0,1,0,45", &error).has_value());
    QVERIFY(!parseCamera("0,0,3,0,0,0,0,1,0", &error).has_value());
    QVERIFY(error.find("expected 10") != std::string::npos);
    QVERIFY(!parseCamera("0,0,3,0,0,0,0,1,0,abc", &error).has_value());
    QVERIFY(!parseCamera("0,0,0,0,0,0,0,1,0,45", &error).has_value());
    QVERIFY(!parseCamera("0,0,3,0,0,0,0,0,1,45", &error).has_value());
    QVERIFY(!parseCamera("0,0,3,0,0,0,0,1,0,180", &error).has_value());
    QVERIFY(!parseCamera("0,0,3,0,0,0,0,1,0,nan", &error).has_value());
}

void TestCamera::keptSpanCases()
{
    const PixelRay ray{{0.0, 0.0, 5.0}, {0.0, 0.0, -1.0}}; // t = distance travelled
    // Plane z = 0 keeping z <= 0 (normal -z): the ray enters the kept side at t = 5.
    const ClipPlane behind{true, {0.0, 0.0, -1.0}, 0.0};
    KeptSpan s = keptSpan(behind, ray, 0.1, 20.0);
    QVERIFY(!s.empty);
    QVERIFY(!s.startsAtNear);
    QCOMPARE(s.tStart, 5.0);
    QCOMPARE(s.tEnd, 20.0);
    // Flipped: keeps z >= 0, the ray leaves the kept side at t = 5.
    s = keptSpan(behind.flipped(), ray, 0.1, 20.0);
    QVERIFY(s.startsAtNear);
    QCOMPARE(s.tStart, 0.1);
    QCOMPARE(s.tEnd, 5.0);
    // Plane parallel to the ray on the clipped side: nothing survives.
    const ClipPlane parallel{true, {1.0, 0.0, 0.0}, -1.0};
    QVERIFY(keptSpan(parallel, ray, 0.1, 20.0).empty);
    // Disabled: the whole [near, far] span.
    s = keptSpan(ClipPlane{}, ray, 0.1, 20.0);
    QVERIFY(!s.empty && s.startsAtNear && s.tStart == 0.1 && s.tEnd == 20.0);
}

QTEST_APPLESS_MAIN(TestCamera)
#include "tst_camera.moc"
