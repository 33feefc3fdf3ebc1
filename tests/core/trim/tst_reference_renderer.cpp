// The CPU reference renderer on analytic scenes whose answers are derived by hand (in the
// comments), compared pixel class by pixel class; pixels whose class is within the
// tessellation tolerance of a boundary are left out and counted, not waved through.
#include "core/catalog/demo_scenes.h"
#include "core/catalog/demo_shapes.h"
#include "core/scene/shape_generators.h"
#include "core/trim/csg_expression.h"
#include "core/trim/reference_renderer.h"
#include "core/trim/trim_shading.h"
#include "core/trim/winding_number.h"

#include <glm/geometric.hpp>

#include <QtTest>

#include <chrono>
#include <cmath>
#include <set>

using namespace trimlab;

namespace {

constexpr int kWidth = 80;
constexpr int kHeight = 60;

Scene sceneOf(std::initializer_list<TriangleMesh> meshes)
{
    Scene scene;
    for (const TriangleMesh& mesh : meshes)
        scene.objects.push_back({"object" + std::to_string(scene.objects.size()), mesh, glm::dmat4(1.0)});
    return scene;
}

Camera cameraAt(const glm::dvec3& eye, const glm::dvec3& target, const Scene& scene,
                const glm::dvec3& up = glm::dvec3(0, 1, 0))
{
    Camera camera;
    camera.eye = eye;
    camera.target = target;
    camera.up = up;
    return withDepthRange(camera, scene.worldBounds());
}

// Radius of the largest ball about `center` inside a convex mesh (min plane distance).
double inscribedRadius(const TriangleMesh& mesh, const glm::dvec3& center = glm::dvec3(0.0))
{
    double r = 1e300;
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
        r = std::min(r, std::abs(glm::dot(glm::normalize(glm::cross(b - a, c - a)), a - center)));
    }
    return r;
}

// Ray parameters where o + t d meets the sphere |x| = r (t1 <= t2); false if it misses.
bool raySphere(const PixelRay& ray, double r, double& t1, double& t2)
{
    const double a = glm::dot(ray.direction, ray.direction);
    const double b = glm::dot(ray.direction, ray.origin);
    const double c = glm::dot(ray.origin, ray.origin) - r * r;
    const double disc = b * b - a * c;
    if (disc < 0.0)
        return false;
    t1 = (-b - std::sqrt(disc)) / a;
    t2 = (-b + std::sqrt(disc)) / a;
    return true;
}

// Distance of the ray's line from the origin.
double axisDistance(const PixelRay& ray)
{
    const glm::dvec3 d = glm::normalize(ray.direction);
    return glm::length(ray.origin - d * glm::dot(ray.origin, d));
}

TrimSettings settingsFor(StaticRule rule, bool trim = true, ClipPlane clip = {})
{
    TrimSettings s;
    s.rule = rule;
    s.trimEnabled = trim;
    s.clip = clip;
    return s;
}

ClipPlane plane(const glm::dvec3& normal, double offset)
{
    return {true, normal, offset};
}

glm::dvec3 shownPoint(const PixelRay& ray, const TrimPixel& pixel)
{
    return ray.origin + double(pixel.viewDepth) * ray.direction;
}

bool onSphere(const glm::dvec3& p, double inscribed, double radius)
{
    const double r = glm::length(p);
    return r >= inscribed - 1e-5 && r <= radius + 1e-5;
}

QString at(int x, int y)
{
    return QString("pixel (%1, %2)").arg(x).arg(y);
}

// Expected content of a pixel: winding at the span start and the shown hit (objectId -1:
// empty pixel).
struct Expect {
    int winding;
    int objectId;
    int facing;
};

void checkPixel(const TrimPixel& p, const Expect& e, int x, int y)
{
    const QString where = at(x, y);
    QVERIFY2(p.windingAtStart == e.winding, qPrintable(where + QString(" winding %1").arg(p.windingAtStart)));
    QVERIFY2(p.objectId == e.objectId, qPrintable(where + QString(" object %1").arg(p.objectId)));
    QVERIFY2(p.facing == e.facing, qPrintable(where + QString(" facing %1").arg(int(p.facing))));
    QVERIFY2(p.covered() == (e.objectId >= 0), qPrintable(where));
}

bool samePixels(const TrimImage& a, const TrimImage& b)
{
    if (a.width != b.width || a.height != b.height)
        return false;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const TrimPixel &p = a.pixels[i], &q = b.pixels[i];
        if (p.viewDepth != q.viewDepth || p.primitiveId != q.primitiveId || p.objectId != q.objectId ||
            p.facing != q.facing || p.windingAtStart != q.windingAtStart)
            return false;
    }
    return true;
}

} // namespace

Q_DECLARE_METATYPE(trimlab::StaticRule)

class TestReferenceRenderer : public QObject {
    Q_OBJECT
private slots:
    void singleSphere();
    void nestedSpheres_data();
    void nestedSpheres();
    void doublyCoveredSphere();
    void cameraInsideSphere();
    void carvedWallsHaveTheirColor();
    void tiltedClipPlane_data();
    void tiltedClipPlane();
    void pushedSphereTunnel();
    void windingMatchesSolidAngle_data();
    void windingMatchesSolidAngle();
    void threadCountDoesNotChangeTheResult();
    void diagnosticsAndStats();
    void emptyInputs();
    void timing35kTriangles();
};

// A unit sphere seen from outside: w(near) = 0 everywhere; where the ray hits, the shown
// point is the front surface (front-facing, 0 -> 1 is a boundary under every rule) at the
// analytic depth within the tessellation (between the unit and the inscribed sphere).
void TestReferenceRenderer::singleSphere()
{
    const TriangleMesh mesh = makeIcosphere(glm::dvec3(0.0), 1.0, 4);
    const double inscribed = inscribedRadius(mesh);
    const Scene scene = sceneOf({mesh});
    const Camera camera = cameraAt({0, 0, 3}, {0, 0, 0}, scene);
    const ReferenceRenderer renderer(scene);
    const std::uint8_t background[3] = {std::uint8_t(std::lround(255 * kBackgroundColor.r)),
                                        std::uint8_t(std::lround(255 * kBackgroundColor.g)),
                                        std::uint8_t(std::lround(255 * kBackgroundColor.b))};
    for (const TrimSettings& settings :
         {settingsFor(StaticRule::AlternatingBorder), settingsFor(StaticRule::Parity),
          settingsFor(StaticRule::PositiveIndex), settingsFor(StaticRule::Parity, false)}) {
        const ReferenceResult result = renderer.render(camera, kWidth, kHeight, settings, 2);
        int inside = 0, outside = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const PixelRay ray = pixelRay(camera, kWidth, kHeight, x, y);
                const TrimPixel& p = result.trim.at(x, y);
                const std::size_t i = result.diagnostics.index(x, y);
                const double rho = axisDistance(ray);
                if (rho < inscribed - 1e-3) {
                    checkPixel(p, {0, 0, 1}, x, y);
                    double t1 = 0, t2 = 0, s1 = 0, s2 = 0;
                    QVERIFY(raySphere(ray, 1.0, t1, t2) && raySphere(ray, inscribed, s1, s2));
                    QVERIFY2(p.viewDepth >= float(t1) * (1 - 1e-6f) && p.viewDepth <= float(s1) * (1 + 1e-6f),
                             qPrintable(at(x, y)));
                    QVERIFY(onSphere(shownPoint(ray, p), inscribed, 1.0));
                    QCOMPARE(result.diagnostics.hitCount[i], 2);
                    // Margin: min over near -> front -> back gaps; the front/back gap closes
                    // towards the silhouette (2·sqrt(1 − rho²) over a depth of ~3.5).
                    const float margin = result.diagnostics.depthMargin[i];
                    QVERIFY2(margin > (rho < 0.5 ? 0.3f : 0.01f),
                             qPrintable(at(x, y) + QString(" margin %1").arg(margin)));
                    QVERIFY(std::isfinite(result.diagnostics.edgeDistancePx[i]));
                    QVERIFY(std::memcmp(result.color.at(x, y), background, 3) != 0);
                    ++inside;
                } else if (rho > 1.0 + 1e-3) {
                    checkPixel(p, {0, -1, 0}, x, y);
                    QCOMPARE(result.diagnostics.hitCount[i], 0);
                    QVERIFY(std::isinf(result.diagnostics.edgeDistancePx[i]));
                    QVERIFY(std::memcmp(result.color.at(x, y), background, 3) == 0);
                    QCOMPARE(int(result.color.at(x, y)[3]), 255);
                    ++outside;
                }
            }
        QVERIFY(inside > 1000 && outside > 1000);
    }
    // Head-on centre pixel: the normal faces the viewer, diffuse ≈ 1: the front color.
    const ReferenceResult result = renderer.render(camera, 81, 61, TrimSettings{}, 1);
    const std::uint8_t* centre = result.color.at(40, 30);
    for (int c = 0; c < 3; ++c)
        QVERIFY(std::abs(int(centre[c]) - int(std::lround(255 * kFrontFacingColor[c]))) <= 1);
}

void TestReferenceRenderer::nestedSpheres_data()
{
    QTest::addColumn<bool>("innerOutward");
    QTest::addColumn<bool>("keepFarHalf");
    QTest::addColumn<StaticRule>("rule");
    QTest::addColumn<bool>("trim");
    // Expected (winding, objectId, facing) in the inner disk and in the annulus.
    QTest::addColumn<int>("diskW");
    QTest::addColumn<int>("diskObject");
    QTest::addColumn<int>("diskFacing");
    QTest::addColumn<int>("annulusW");
    QTest::addColumn<int>("annulusObject");
    QTest::addColumn<int>("annulusFacing");
    using R = StaticRule;
    // Outer (object 0, r = 1) and inner (object 1, r = 0.5) outward; plane z = 0 keeping
    // the far half: w = 2 in the inner disk, 1 in the annulus. Beyond the plane the disk
    // ray meets inner-back (2 -> 1) then outer-back (1 -> 0); the annulus ray outer-back.
    // alternating: 2, 1 in; 0 out -> outer back. positive: same. parity: 2 out, 1 in ->
    // inner back. Untrimmed: the first hit, inner back.
    QTest::newRow("outward/far/alternating")
        << true << true << R::AlternatingBorder << true << 2 << 0 << -1 << 1 << 0 << -1;
    QTest::newRow("outward/far/positive") << true << true << R::PositiveIndex << true << 2 << 0 << -1 << 1 << 0 << -1;
    QTest::newRow("outward/far/parity") << true << true << R::Parity << true << 2 << 1 << -1 << 1 << 0 << -1;
    QTest::newRow("outward/far/untrimmed") << true << true << R::Parity << false << 2 << 1 << -1 << 1 << 0 << -1;
    // Inner sphere inward (a hollow ball): w = 0 in the disk, 1 in the annulus. The inner
    // sphere's far side faces the camera (front-facing, 0 -> 1): a boundary for every rule.
    QTest::newRow("inward/far/alternating")
        << false << true << R::AlternatingBorder << true << 0 << 1 << 1 << 1 << 0 << -1;
    QTest::newRow("inward/far/positive") << false << true << R::PositiveIndex << true << 0 << 1 << 1 << 1 << 0 << -1;
    QTest::newRow("inward/far/parity") << false << true << R::Parity << true << 0 << 1 << 1 << 1 << 0 << -1;
    // Keeping the near half (plane normal +z): span [near, plane], w(near) = 0, the outer
    // front surface 0 -> 1 is shown for every rule and both inner orientations.
    QTest::newRow("outward/near/parity") << true << false << R::Parity << true << 0 << 0 << 1 << 0 << 0 << 1;
    QTest::newRow("inward/near/alternating")
        << false << false << R::AlternatingBorder << true << 0 << 0 << 1 << 0 << 0 << 1;
}

void TestReferenceRenderer::nestedSpheres()
{
    QFETCH(bool, innerOutward);
    QFETCH(bool, keepFarHalf);
    QFETCH(StaticRule, rule);
    QFETCH(bool, trim);
    QFETCH(int, diskW);
    QFETCH(int, diskObject);
    QFETCH(int, diskFacing);
    QFETCH(int, annulusW);
    QFETCH(int, annulusObject);
    QFETCH(int, annulusFacing);
    const TriangleMesh outer = makeIcosphere(glm::dvec3(0.0), 1.0, 4);
    const TriangleMesh inner = makeIcosphere(glm::dvec3(0.0), 0.5, 3, innerOutward);
    const double kOuter = inscribedRadius(outer);
    const double kInner = inscribedRadius(inner);
    const Scene scene = sceneOf({outer, inner});
    const Camera camera = cameraAt({0, 0, 3}, {0, 0, 0}, scene);
    const ClipPlane clip = keepFarHalf ? plane({0, 0, -1}, 0.0) : plane({0, 0, 1}, 0.0);
    const ReferenceResult result =
        ReferenceRenderer(scene).render(camera, kWidth, kHeight, settingsFor(rule, trim, clip), 2);
    int counts[3] = {};
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const PixelRay ray = pixelRay(camera, kWidth, kHeight, x, y);
            const glm::dvec3 onPlane = ray.origin + 3.0 * ray.direction; // view depth 3 is z = 0
            const double rho = glm::length(onPlane);
            const TrimPixel& p = result.trim.at(x, y);
            if (rho < kInner - 2e-3) {
                checkPixel(p, {diskW, diskObject, diskFacing}, x, y);
                ++counts[0];
            } else if (rho > 0.5 + 2e-3 && rho < kOuter - 2e-3) {
                checkPixel(p, {annulusW, annulusObject, annulusFacing}, x, y);
                ++counts[1];
            } else if (rho > 1.0 + 2e-3) {
                if (keepFarHalf) // beyond the plane the diverging ray misses everything
                    checkPixel(p, {0, -1, 0}, x, y);
                ++counts[2];
            } else {
                continue;
            }
            if (p.covered()) { // the shown point lies on the sphere it claims, on the kept side
                const glm::dvec3 q = shownPoint(ray, p);
                QVERIFY(p.objectId == 0 ? onSphere(q, kOuter, 1.0) : onSphere(q, kInner, 0.5));
                QVERIFY(keepFarHalf ? q.z < 0.0 : q.z > 0.0);
            }
        }
    QVERIFY(counts[0] > 200 && counts[1] > 500 && counts[2] > 500);
}

// The same sphere twice (objects 0 and 1): w = 2 inside. Coincident hits are ordered by
// object id. From outside: F(o0) 0 -> 1 is shown under every rule. With the far half
// kept: w(plane) = 2; B(o0) 2 -> 1, B(o1) 1 -> 0: alternating and positive show o1's back
// face, parity (2 out, 1 in) o0's. Every such pixel is an exact depth tie: margin 0.
void TestReferenceRenderer::doublyCoveredSphere()
{
    const TriangleMesh mesh = makeIcosphere(glm::dvec3(0.0), 1.0, 3);
    const double k = inscribedRadius(mesh);
    const Scene scene = sceneOf({mesh, mesh});
    const Camera camera = cameraAt({0, 0, 3}, {0, 0, 0}, scene);
    const ReferenceRenderer renderer(scene);
    struct Case {
        TrimSettings settings;
        Expect expect;
    };
    const ClipPlane far = plane({0, 0, -1}, 0.0);
    const Case cases[] = {
        {settingsFor(StaticRule::AlternatingBorder), {0, 0, 1}},
        {settingsFor(StaticRule::Parity), {0, 0, 1}},
        {settingsFor(StaticRule::AlternatingBorder, true, far), {2, 1, -1}},
        {settingsFor(StaticRule::PositiveIndex, true, far), {2, 1, -1}},
        {settingsFor(StaticRule::Parity, true, far), {2, 0, -1}},
    };
    for (const Case& c : cases) {
        const ReferenceResult result = renderer.render(camera, kWidth, kHeight, c.settings, 2);
        int checked = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const PixelRay ray = pixelRay(camera, kWidth, kHeight, x, y);
                const double rho =
                    c.settings.clip.enabled ? glm::length(ray.origin + 3.0 * ray.direction) : axisDistance(ray);
                if (rho >= k - 2e-3)
                    continue;
                checkPixel(result.trim.at(x, y), c.expect, x, y);
                QCOMPARE(result.diagnostics.depthMargin[result.diagnostics.index(x, y)], 0.0f);
                QCOMPARE(result.diagnostics.hitCount[result.diagnostics.index(x, y)], 4);
                ++checked;
            }
        QVERIFY(checked > 1000);
    }
}

// Eye at the centre of a unit sphere: every ray has one hit, a back face beyond the near
// plane; w(near) = +1 and 1 -> 0 is a boundary under every rule.
void TestReferenceRenderer::cameraInsideSphere()
{
    const TriangleMesh mesh = makeIcosphere(glm::dvec3(0.0), 1.0, 4);
    const double k = inscribedRadius(mesh);
    const Scene scene = sceneOf({mesh});
    const Camera camera = cameraAt({0, 0, 0}, {0.2, -0.1, -1}, scene);
    QVERIFY(camera.zNear < 0.01 && camera.zFar > 1.0);
    const ReferenceRenderer renderer(scene);
    for (StaticRule rule : {StaticRule::AlternatingBorder, StaticRule::Parity, StaticRule::PositiveIndex}) {
        const ReferenceResult result = renderer.render(camera, kWidth, kHeight, settingsFor(rule), 2);
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const TrimPixel& p = result.trim.at(x, y);
                checkPixel(p, {1, 0, -1}, x, y);
                QVERIFY(onSphere(shownPoint(pixelRay(camera, kWidth, kHeight, x, y), p), k, 1.0));
            }
        QCOMPARE(result.stats.coveredPixels, std::uint64_t(kWidth * kHeight));
    }
    const ReferenceResult result = renderer.render(camera, 81, 61, TrimSettings{}, 1);
    const std::uint8_t* centre = result.color.at(40, 30);
    for (int c = 0; c < 3; ++c) // looking at the inside head-on: the back color, diffuse ≈ 1
        QVERIFY(std::abs(int(centre[c]) - int(std::lround(255 * kBackFacingColor[c]))) <= 1);
}

// A ball bitten out of the top of a sphere (CSG 0 - 1), seen from above: the cavity's
// floor is the ball's inside — a wall the difference carved, in its own color, not the
// blue of an inside seen through a cut (which the sphere alone, cut open, still shows).
// The subtracted operands are those after the first of a difference, at any depth.
void TestReferenceRenderer::carvedWallsHaveTheirColor()
{
    const auto subtracted = [](const char* text) {
        return csgSubtractedMask(parseCsgExpression(text, nullptr).value());
    };
    QCOMPARE(subtracted("0 - 1"), 0b10u);
    QCOMPARE(subtracted("0 - 1 - 2"), 0b110u);
    QCOMPARE(subtracted("(0 | 1) - 2"), 0b100u);
    QCOMPARE(subtracted("0 - (1 - 2)"), 0b110u);
    QCOMPARE(subtracted("0 | 1 & 2"), 0u);
    QCOMPARE(csgSubtractedMask(CsgExpression{}), 0u);

    const Scene scene = sceneOf({makeIcosphere(glm::dvec3(0.0), 1.0, 4), makeIcosphere({0.0, 0.0, 1.0}, 0.5, 3)});
    const Camera camera = cameraAt({0.0, 0.0, 4.0}, {0.0, 0.0, 0.0}, scene);
    TrimSettings bitten = settingsFor(StaticRule::Nonzero);
    bitten.csg.expression = parseCsgExpression("0 - 1", nullptr).value();
    const ReferenceRenderer renderer(scene);
    const ReferenceResult result = renderer.render(camera, 81, 61, bitten, 1);
    const TrimPixel& floor = result.trim.at(40, 30);
    QCOMPARE(floor.objectId, 1);
    QCOMPARE(int(floor.facing), -1);
    const std::uint8_t* centre = result.color.at(40, 30);
    for (int c = 0; c < 3; ++c) // the floor head-on: diffuse ≈ 1
        QVERIFY2(std::abs(int(centre[c]) - int(std::lround(255 * kCarvedWallColor[c]))) <= 2,
                 qPrintable(QStringLiteral("channel %1: %2").arg(c).arg(centre[c])));

    const ReferenceResult cut =
        ReferenceRenderer(sceneOf({makeIcosphere(glm::dvec3(0.0), 1.0, 4)}))
            .render(camera, 81, 61, settingsFor(StaticRule::Nonzero, true, ClipPlane{true, {0, 0, -1}, 0.0}), 1);
    const std::uint8_t* inside = cut.color.at(40, 30);
    for (int c = 0; c < 3; ++c)
        QVERIFY(std::abs(int(inside[c]) - int(std::lround(255 * kBackFacingColor[c]))) <= 2);
}

void TestReferenceRenderer::tiltedClipPlane_data()
{
    QTest::addColumn<bool>("flip");
    QTest::addColumn<int>("minFront");
    QTest::addColumn<int>("minBack");
    // The eye is clipped away by the plane: spans start at the plane; all three classes.
    QTest::newRow("plane") << false << 100 << 300;
    // The eye is kept: spans [near, plane]; w(near) = 0, a back face is never shown.
    QTest::newRow("flipped") << true << 300 << 0;
}

// A unit sphere cut by a plane that is not view aligned, from an off-axis eye. Expected
// answer from the analytic sphere (front hit t1, back hit t2) and the plane crossing tp:
// span from the near plane to tp: front shown iff t1 < tp; span from tp on: tp < t1 ->
// front shown (w 0), t1 < tp < t2 -> back shown with w 1 (a cut into the solid),
// tp > t2 -> nothing. Cases within the tessellation band of t1 or t2 are skipped.
void TestReferenceRenderer::tiltedClipPlane()
{
    QFETCH(bool, flip);
    QFETCH(int, minFront);
    QFETCH(int, minBack);
    const TriangleMesh mesh = makeIcosphere(glm::dvec3(0.0), 1.0, 4);
    const double k = inscribedRadius(mesh);
    const Scene scene = sceneOf({mesh});
    const Camera camera = cameraAt({0.5, 0.4, 3.0}, {0, 0, 0}, scene);
    ClipPlane clip = plane({0.6, -0.2, -0.7}, 0.1);
    if (flip)
        clip = clip.flipped();
    const ReferenceResult result = ReferenceRenderer(scene).render(
        camera, kWidth, kHeight, settingsFor(StaticRule::AlternatingBorder, true, clip));
    int counts[4] = {}; // front shown, back shown, empty with w 0, skipped
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const PixelRay ray = pixelRay(camera, kWidth, kHeight, x, y);
            const TrimPixel& p = result.trim.at(x, y);
            double t1 = 0, t2 = 0, s1 = 0, s2 = 0;
            const double rho = axisDistance(ray);
            if (rho > 1.0 + 1e-3) {
                checkPixel(p, {0, -1, 0}, x, y);
                ++counts[2];
                continue;
            }
            if (rho > k - 1e-3 || !raySphere(ray, 1.0, t1, t2) || !raySphere(ray, k, s1, s2)) {
                ++counts[3];
                continue;
            }
            // f(t) = n·(o + t d) + offset, linear; kept where f >= 0.
            const double f0 = clip.evaluate(ray.origin);
            const double slope = glm::dot(clip.normal, ray.direction);
            const double tp = -f0 / slope;
            const bool startsKept = f0 + slope * camera.zNear >= 0.0;
            const double eps = 1e-3;
            const bool nearFront = tp > t1 - eps && tp < s1 + eps; // ambiguous: tp in the front band
            const bool nearBack = tp > s2 - eps && tp < t2 + eps;
            if (nearFront || nearBack) {
                ++counts[3];
                continue;
            }
            Expect e{0, -1, 0};
            if (startsKept) {
                if (tp > s1 || tp < camera.zNear) // tp behind the eye: the whole ray is kept
                    e = {0, 0, 1};
            } else if (tp < t1) {
                e = {0, 0, 1};
            } else if (tp < s2) {
                e = {1, 0, -1};
            }
            checkPixel(p, e, x, y);
            ++counts[e.objectId < 0 ? 2 : e.facing > 0 ? 0 : 1];
        }
    qInfo("front %d, back %d, empty %d, skipped %d", counts[0], counts[1], counts[2], counts[3]);
    QVERIFY(counts[0] >= minFront && counts[1] >= minBack && counts[2] > 300);
    if (flip)
        QCOMPARE(counts[1], 0);
    QVERIFY(counts[3] < kWidth * kHeight / 10);
}

// The pushed sphere seen from above along its axis (odd image: the centre ray is the
// axis itself, exactly through both pole vertices). Inside the finger's opening (axis
// distance < 0.2 at the south cap) the ray meets the south cap from above (back-facing,
// w 0 -> -1) and the finger tip (front-facing, -1 -> 0). Alternating border: -1 (mod 4 = 3)
// and 0 are both out: both trimmed, the ray sees through the hole (the genus change).
// Positive index: also out/out. Parity and untrimmed: the south cap at depth 4 + sqrt(1 - r²).
void TestReferenceRenderer::pushedSphereTunnel()
{
    const Scene scene = *makeDemoScene("pushed-sphere");
    const Camera camera = cameraAt({0, 4, 0}, {0, 0, 0}, scene, {0, 0, -1});
    const int w = 65, h = 49;
    const ReferenceRenderer renderer(scene);
    const ReferenceResult alternating = renderer.render(camera, w, h, settingsFor(StaticRule::AlternatingBorder));
    const ReferenceResult positive = renderer.render(camera, w, h, settingsFor(StaticRule::PositiveIndex));
    const ReferenceResult parity = renderer.render(camera, w, h, settingsFor(StaticRule::Parity));
    const ReferenceResult untrimmed = renderer.render(camera, w, h, settingsFor(StaticRule::Parity, false));
    int tunnel = 0, body = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const PixelRay ray = pixelRay(camera, w, h, x, y);
            const glm::dvec3 atCap = ray.origin + 5.0 * ray.direction; // view depth 5: y = -1
            const double r = glm::length(glm::dvec2(atCap.x, atCap.z));
            if (r < 0.2) {
                checkPixel(alternating.trim.at(x, y), {0, -1, 0}, x, y);
                checkPixel(positive.trim.at(x, y), {0, -1, 0}, x, y);
                for (const ReferenceResult* shown : {&parity, &untrimmed}) {
                    const TrimPixel& p = shown->trim.at(x, y);
                    checkPixel(p, {0, 0, -1}, x, y);
                    QVERIFY(std::abs(p.viewDepth - (4.0 + std::sqrt(1.0 - r * r))) < 0.01);
                }
                QCOMPARE(alternating.diagnostics.hitCount[alternating.diagnostics.index(x, y)], 2);
                ++tunnel;
            } else if (r > 0.7 && r < 0.9) { // the sphere's upper body: front-facing, kept
                checkPixel(alternating.trim.at(x, y), {0, 0, 1}, x, y);
                ++body;
            }
        }
    QVERIFY(tunnel > 20 && body > 100);
    QVERIFY(!alternating.trim.at(w / 2, h / 2).covered()); // the axis ray through the poles
    QVERIFY(parity.trim.at(w / 2, h / 2).covered());
}

void TestReferenceRenderer::windingMatchesSolidAngle_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("expectedLowest");
    QTest::addColumn<int>("expectedHighest");
    QTest::newRow("pushed-sphere") << "pushed-sphere" << -1 << 1;
    QTest::newRow("crossing-loop") << "crossing-loop" << 0 << 2;
}

// End to end: the winding index the walk counts at a clip-plane start equals the
// generalized winding number (solid angles, no rays) at that point, on the self-crossing
// demos, and every component kind of the demo shows up.
void TestReferenceRenderer::windingMatchesSolidAngle()
{
    QFETCH(QString, name);
    QFETCH(int, expectedLowest);
    QFETCH(int, expectedHighest);
    const Scene scene = *makeDemoScene(name.toStdString());
    const bool loop = name == "crossing-loop";
    // Pushed sphere: from the side, cut through the axis. Loop: from above, cut near y = 0.
    const Camera camera =
        loop ? cameraAt({0.3, 4, 0.2}, {0, 0, 0}, scene, {0, 0, -1}) : cameraAt({0.2, -0.5, 4}, {0, -0.5, 0}, scene);
    const ClipPlane clip = loop ? plane({0.1, -1, 0.05}, 0.0) : plane({0.05, 0.02, -1}, 0.0);
    const int w = 48, h = 36;
    const ReferenceResult result =
        ReferenceRenderer(scene).render(camera, w, h, settingsFor(StaticRule::AlternatingBorder, true, clip));
    std::set<int> seen;
    int compared = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const PixelRay ray = pixelRay(camera, w, h, x, y);
            const KeptSpan span = keptSpan(clip, ray, camera.zNear, camera.zFar);
            if (span.empty || span.startsAtNear ||
                result.diagnostics.depthMargin[result.diagnostics.index(x, y)] < 1e-3f)
                continue;
            const double wSolid = solidAngleWindingNumber(scene, ray.origin + span.tStart * ray.direction);
            const int windingAtStart = result.trim.at(x, y).windingAtStart;
            QVERIFY2(std::abs(wSolid - windingAtStart) < 1e-3,
                     qPrintable(at(x, y) + QString(": walk %1, solid angle %2").arg(windingAtStart).arg(wSolid)));
            seen.insert(windingAtStart);
            ++compared;
        }
    QVERIFY(compared > 300);
    QCOMPARE(*seen.begin(), expectedLowest);
    QCOMPARE(*seen.rbegin(), expectedHighest);
    QCOMPARE(int(seen.size()), expectedHighest - expectedLowest + 1);
}

void TestReferenceRenderer::threadCountDoesNotChangeTheResult()
{
    const Scene scene = *makeDemoScene("crossing-loop");
    const Camera camera = fitCamera(scene.worldBounds(), 64.0 / 48.0);
    const TrimSettings settings = settingsFor(StaticRule::AlternatingBorder, true, plane({0.2, 0.1, -1}, 0.1));
    const ReferenceRenderer renderer(scene);
    const ReferenceResult one = renderer.render(camera, 64, 48, settings, 1);
    for (unsigned threads : {2u, 3u, 0u}) {
        const ReferenceResult many = renderer.render(camera, 64, 48, settings, threads);
        QVERIFY(samePixels(one.trim, many.trim));
        QVERIFY(one.color.rgba == many.color.rgba);
        QVERIFY(one.diagnostics.depthMargin == many.diagnostics.depthMargin);
        QVERIFY(one.diagnostics.edgeDistancePx == many.diagnostics.edgeDistancePx);
        QVERIFY(one.diagnostics.hitCount == many.diagnostics.hitCount);
        QCOMPARE(many.stats.totalHits, one.stats.totalHits);
        QCOMPARE(many.stats.coveredPixels, one.stats.coveredPixels);
        QCOMPARE(many.stats.maxHitsPerPixel, one.stats.maxHitsPerPixel);
    }
    QCOMPARE(one.stats.threads, 1u);
}

// A large front-facing triangle in z = 0 whose only visible edge is the line x = 0 (the
// image's centre column): edgeDistancePx is |x + 0.5 - w/2| right of it, and empty left.
// (An open surface: w(near) counted from the far side is -1, so show it untrimmed.)
void TestReferenceRenderer::diagnosticsAndStats()
{
    TriangleMesh big;
    big.positions = {{0, -20, 0}, {20, 20, 0}, {0, 20, 0}};
    big.triangles = {{0, 1, 2}};
    const Scene scene = sceneOf({big});
    Camera camera;
    camera.zNear = 0.5;
    camera.zFar = 10.0;
    const ReferenceResult result =
        ReferenceRenderer(scene).render(camera, kWidth, kHeight, settingsFor(StaticRule::Parity, false), 2);
    std::uint64_t hits = 0, covered = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t i = result.diagnostics.index(x, y);
            const TrimPixel& p = result.trim.at(x, y);
            hits += std::uint64_t(result.diagnostics.hitCount[i]);
            covered += p.covered() ? 1 : 0;
            QVERIFY2(p.covered() == (x >= kWidth / 2), qPrintable(at(x, y)));
            if (!p.covered()) {
                QVERIFY(std::isinf(result.diagnostics.edgeDistancePx[i]));
                continue;
            }
            QCOMPARE(int(p.facing), 1);
            QCOMPARE(p.windingAtStart, -1);
            QVERIFY(std::abs(p.viewDepth - 3.0f) < 1e-5f);
            QVERIFY(std::abs(result.diagnostics.edgeDistancePx[i] - (x + 0.5f - kWidth / 2)) < 1e-3f);
            // Window near(0.5) < hit(3) < far(10): margin = min(2.5/3, 7/10).
            QVERIFY(std::abs(result.diagnostics.depthMargin[i] - 0.7f) < 1e-4f);
        }
    QCOMPARE(result.stats.totalHits, hits);
    QCOMPARE(result.stats.coveredPixels, covered);
    QCOMPARE(result.stats.maxHitsPerPixel, 1);
    QCOMPARE(covered, std::uint64_t(kWidth * kHeight / 2));
    QVERIFY(result.stats.wallMs >= 0.0);
}

void TestReferenceRenderer::emptyInputs()
{
    const ReferenceRenderer emptyScene{Scene{}};
    const ReferenceResult result = emptyScene.render(Camera{}, 16, 12, TrimSettings{});
    QCOMPARE(result.trim.width, 16);
    QCOMPARE(result.stats.coveredPixels, std::uint64_t(0));
    QVERIFY(!result.trim.at(3, 3).covered());
    const ReferenceResult none = emptyScene.render(Camera{}, 0, 12, TrimSettings{});
    QCOMPARE(none.trim.width, 0);
    QVERIFY(none.color.rgba.empty());
    QVERIFY(none.trim.pixels.empty());
}

// Not asserted: prints the reference's speed on ~35k-triangle self-crossing meshes.
void TestReferenceRenderer::timing35kTriangles()
{
    struct Case {
        const char* name;
        TriangleMesh mesh;
        glm::dvec3 view;
        ClipPlane clip;
    };
    const Case cases[] = {
        {"crossing-loop 720x24", makeCrossingLoop(720, 24), {0.1, -1.0, 0.3}, plane({0, -1, 0}, 0.0)},
        {"pushed-sphere 192x94", makePushedSphere(192, 94), {-0.35, -0.45, -1.0}, plane({0.05, 0.02, -1}, 0.0)},
    };
    for (const Case& c : cases) {
        Scene scene;
        scene.objects.push_back({c.name, c.mesh, glm::dmat4(1.0)});
        const auto start = std::chrono::steady_clock::now();
        const ReferenceRenderer renderer(scene);
        const double buildMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        const Camera camera = fitCamera(scene.worldBounds(), 1.0, c.view);
        const TrimSettings settings = settingsFor(StaticRule::AlternatingBorder, true, c.clip);
        double best = 1e300;
        ReferenceStats stats;
        for (int run = 0; run < 2; ++run) {
            stats = renderer.render(camera, 512, 512, settings, 2).stats;
            best = std::min(best, stats.wallMs);
        }
        qInfo("reference %s: %zu triangles, BVH %zu nodes in %.1f ms; 512x512, %u threads: %.1f ms (best of 2), "
              "%llu hits, max %d per pixel, %llu covered pixels",
              c.name, scene.triangleCount(), renderer.bvh().nodeCount(), buildMs, stats.threads, best,
              static_cast<unsigned long long>(stats.totalHits), stats.maxHitsPerPixel,
              static_cast<unsigned long long>(stats.coveredPixels));
        QVERIFY(stats.coveredPixels > 0);
    }
}

QTEST_APPLESS_MAIN(TestReferenceRenderer)
#include "tst_reference_renderer.moc"
