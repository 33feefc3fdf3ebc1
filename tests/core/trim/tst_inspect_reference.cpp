// The CPU reference's capping, clip boxes, n-ary CSG, collision and coplanar answers on
// scenes of tessellated spheres, checked pixel by pixel against analytic spheres (ray–
// sphere intervals and a slab test for the box), independent of the walk code. A sphere
// tessellated with vertices on radius r lies between its inscribed radius and r: a pixel
// is compared only where the analytic answer is the same for both radii (the others are
// counted and must stay few), so tessellation never decides a comparison.
#include "core/scene/shape_generators.h"
#include "core/trim/reference_renderer.h"

#include <glm/geometric.hpp>

#include <QtTest>

#include <optional>

using namespace trimlab;

namespace {

constexpr int kWidth = 96;
constexpr int kHeight = 72;

struct Ball {
    glm::dvec3 center;
    double radius;
};

TriangleMesh ballMesh(const Ball& ball)
{
    return makeIcosphere(ball.center, ball.radius, 4);
}

// Largest ball about the centre inside the tessellation (min plane distance).
double inscribed(const TriangleMesh& mesh, const glm::dvec3& center)
{
    double r = 1e300;
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
        r = std::min(r, std::abs(glm::dot(glm::normalize(glm::cross(b - a, c - a)), a - center)));
    }
    return r;
}

// [t1, t2] of the ray inside the ball of radius r, if any.
std::optional<std::pair<double, double>> interval(const PixelRay& ray, const glm::dvec3& center, double r)
{
    const glm::dvec3 o = ray.origin - center;
    const double a = glm::dot(ray.direction, ray.direction);
    const double b = glm::dot(ray.direction, o);
    const double disc = b * b - a * (glm::dot(o, o) - r * r);
    if (disc <= 0.0)
        return std::nullopt;
    return std::make_pair((-b - std::sqrt(disc)) / a, (-b + std::sqrt(disc)) / a);
}

Scene sceneOf(const std::vector<TriangleMesh>& meshes)
{
    Scene scene;
    for (const TriangleMesh& mesh : meshes)
        scene.objects.push_back({"ball" + std::to_string(scene.objects.size()), mesh, glm::dmat4(1.0)});
    return scene;
}

Camera viewOf(const Scene& scene)
{
    return fitCamera(scene.worldBounds(), double(kWidth) / kHeight, glm::dvec3(-0.4, -0.5, -1.0));
}

// What a pixel should show, as (object, facing) or a cap; `nothing` when empty.
struct Expected {
    int objectId = -1;
    int facing = 0;
    int capPlane = -1;
    bool operator==(const Expected&) const = default;
};

Expected shownBy(const TrimPixel& p)
{
    return {p.capPlane >= 0 ? -1 : p.objectId, p.capPlane >= 0 ? 0 : p.facing, p.capPlane};
}

// The analytic CSG answer for two balls A (object 0), B (object 1) on a ray from outside
// both (the camera is), or nullopt when the ray misses both.
Expected csgAnswer(const std::string& op, const std::optional<std::pair<double, double>>& a,
                   const std::optional<std::pair<double, double>>& b)
{
    const double inf = std::numeric_limits<double>::infinity();
    const auto [a1, a2] = a ? *a : std::make_pair(inf, inf);
    const auto [b1, b2] = b ? *b : std::make_pair(inf, inf);
    if (op == "union") {
        if (!a && !b)
            return {};
        return a1 <= b1 ? Expected{0, 1} : Expected{1, 1};
    }
    if (op == "intersection") {
        if (!a || !b || std::max(a1, b1) >= std::min(a2, b2))
            return {};
        return a1 >= b1 ? Expected{0, 1} : Expected{1, 1};
    }
    // difference A − B: A's front unless it lies inside B; then B's back face if that
    // lies inside A.
    if (!a)
        return {};
    if (!b || a1 < b1 || a1 > b2)
        return {0, 1};
    return b2 < a2 ? Expected{1, -1} : Expected{};
}

} // namespace

class TestInspectReference : public QObject {
    Q_OBJECT
private slots:
    void capsABallCutByABox();
    void csgOfTwoBalls_data();
    void csgOfTwoBalls();
    void threeOperandTree();
    void collisionsOfOverlappingBalls();
    void coplanarDuplicate();
};

void TestInspectReference::capsABallCutByABox()
{
    const Ball ball{{0.0, 0.0, 0.0}, 1.0};
    const TriangleMesh mesh = ballMesh(ball);
    const double rIn = inscribed(mesh, ball.center);
    const Scene scene = sceneOf({mesh});
    const Camera camera = viewOf(scene);
    TrimSettings settings;
    settings.setClipSet(ClipSet::box({-0.6, -0.5, -0.4}, {0.5, 0.7, 2.0}));
    settings.cap.enabled = true;
    const ReferenceResult r = ReferenceRenderer(scene).render(camera, kWidth, kHeight, settings);
    int caps = 0, compared = 0, skipped = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const PixelRay ray = pixelRay(camera, kWidth, kHeight, x, y);
            // Slab test: the entering face of the box and the point there.
            double tIn = camera.zNear, tOut = camera.zFar;
            int face = -1;
            const glm::dvec3 lower(-0.6, -0.5, -0.4), upper(0.5, 0.7, 2.0);
            for (int axis = 0; axis < 3; ++axis) {
                const double t0 = (lower[axis] - ray.origin[axis]) / ray.direction[axis];
                const double t1 = (upper[axis] - ray.origin[axis]) / ray.direction[axis];
                const double enter = std::min(t0, t1);
                if (enter > tIn) {
                    tIn = enter;
                    face = 2 * axis + (t0 < t1 ? 0 : 1);
                }
                tOut = std::min(tOut, std::max(t0, t1));
            }
            const TrimPixel& p = r.trim.at(x, y);
            if (tIn >= tOut || face < 0) {
                QVERIFY2(!p.isCap(), qPrintable(QString("(%1, %2) outside the box shows a cap").arg(x).arg(y)));
                continue;
            }
            const double distance = glm::length(ray.origin + tIn * ray.direction);
            const double margin = 1e-3; // box edges and the ball's tessellation band
            const bool nearEdge =
                tOut - tIn < margin || std::abs(distance - rIn) < margin || std::abs(distance - ball.radius) < margin;
            if ((distance > rIn && distance < ball.radius) || nearEdge) {
                ++skipped;
                continue;
            }
            ++compared;
            const bool capExpected = distance < rIn;
            QVERIFY2(p.isCap() == capExpected, qPrintable(QString("(%1, %2)").arg(x).arg(y)));
            if (capExpected) {
                ++caps;
                QCOMPARE(int(p.capPlane), face);
                QVERIFY(std::abs(double(p.viewDepth) - tIn) <= 1e-6 * tIn);
                QCOMPARE(p.primitiveId, -1);
            }
        }
    }
    qInfo("%d caps among %d compared pixels, %d skipped", caps, compared, skipped);
    QVERIFY(caps > 300);
    QVERIFY(skipped < compared / 10);
}

void TestInspectReference::csgOfTwoBalls_data()
{
    QTest::addColumn<QString>("op");
    QTest::addColumn<QString>("expression");
    QTest::newRow("union") << "union"
                           << "0 | 1";
    QTest::newRow("intersection") << "intersection"
                                  << "0 & 1";
    QTest::newRow("difference") << "difference"
                                << "0 - 1";
}

void TestInspectReference::csgOfTwoBalls()
{
    QFETCH(QString, op);
    QFETCH(QString, expression);
    const Ball a{{-0.35, 0.05, 0.0}, 0.7};
    const Ball b{{0.35, -0.05, 0.1}, 0.65};
    const TriangleMesh meshA = ballMesh(a), meshB = ballMesh(b);
    const double aIn = inscribed(meshA, a.center), bIn = inscribed(meshB, b.center);
    const Scene scene = sceneOf({meshA, meshB});
    const Camera camera = viewOf(scene);
    TrimSettings settings;
    settings.rule = StaticRule::PositiveIndex;
    settings.csg.expression = parseCsgExpression(expression.toStdString(), nullptr).value();
    const ReferenceResult r = ReferenceRenderer(scene).render(camera, kWidth, kHeight, settings);
    int compared = 0, skipped = 0, covered = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const PixelRay ray = pixelRay(camera, kWidth, kHeight, x, y);
            const Expected outer =
                csgAnswer(op.toStdString(), interval(ray, a.center, a.radius), interval(ray, b.center, b.radius));
            const Expected inner =
                csgAnswer(op.toStdString(), interval(ray, a.center, aIn), interval(ray, b.center, bIn));
            if (!(outer == inner)) {
                ++skipped;
                continue;
            }
            ++compared;
            covered += outer.objectId >= 0 ? 1 : 0;
            QVERIFY2(shownBy(r.trim.at(x, y)) == outer,
                     qPrintable(QString("%1 at (%2, %3): shows object %4 facing %5, expected %6 facing %7")
                                    .arg(op)
                                    .arg(x)
                                    .arg(y)
                                    .arg(r.trim.at(x, y).objectId)
                                    .arg(r.trim.at(x, y).facing)
                                    .arg(outer.objectId)
                                    .arg(outer.facing)));
        }
    }
    qInfo("%s: %d compared (%d covered), %d skipped on the tessellation band", qPrintable(op), compared, covered,
          skipped);
    QVERIFY(covered > 200);
    QVERIFY(skipped < compared / 10);
}

void TestInspectReference::threeOperandTree()
{
    // (A | B) − C with C a ball in front of the pair's overlap: pixels whose ray meets C
    // in front of the union show C's back face (where inside A or B) or A/B's front behind
    // C; checked against the analytic answer on the robust pixels.
    const Ball a{{-0.4, 0.0, 0.0}, 0.6}, b{{0.4, 0.0, 0.0}, 0.6}, c{{0.0, 0.1, 0.5}, 0.45};
    const std::vector<TriangleMesh> meshes = {ballMesh(a), ballMesh(b), ballMesh(c)};
    const double in[3] = {inscribed(meshes[0], a.center), inscribed(meshes[1], b.center),
                          inscribed(meshes[2], c.center)};
    const Scene scene = sceneOf(meshes);
    const Camera camera = viewOf(scene);
    TrimSettings settings;
    settings.rule = StaticRule::PositiveIndex;
    settings.csg.expression = parseCsgExpression("0 | 1 - 2", nullptr).value();
    const ReferenceResult r = ReferenceRenderer(scene).render(camera, kWidth, kHeight, settings);
    // The answer along a ray: the first t in (A ∪ B) \ C, from the sorted interval ends.
    auto answer = [&](const PixelRay& ray, bool useInscribed) -> Expected {
        const Ball balls[3] = {a, b, c};
        std::optional<std::pair<double, double>> iv[3];
        for (int i = 0; i < 3; ++i)
            iv[i] = interval(ray, balls[i].center, useInscribed ? in[i] : balls[i].radius);
        struct Event {
            double t;
            int object;
            int facing;
        };
        std::vector<Event> events;
        for (int i = 0; i < 3; ++i)
            if (iv[i]) {
                events.push_back({iv[i]->first, i, 1});
                events.push_back({iv[i]->second, i, -1});
            }
        std::sort(events.begin(), events.end(), [](const Event& l, const Event& m) { return l.t < m.t; });
        bool inside[3] = {false, false, false};
        for (const Event& e : events) {
            inside[e.object] = e.facing > 0;
            if ((inside[0] || inside[1]) && !inside[2])
                return {e.object, e.facing};
        }
        return {};
    };
    int compared = 0, skipped = 0, backOfC = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const PixelRay ray = pixelRay(camera, kWidth, kHeight, x, y);
            const Expected outer = answer(ray, false);
            if (!(outer == answer(ray, true))) {
                ++skipped;
                continue;
            }
            ++compared;
            backOfC += outer.objectId == 2 ? 1 : 0;
            QVERIFY2(shownBy(r.trim.at(x, y)) == outer, qPrintable(QString("(%1, %2)").arg(x).arg(y)));
        }
    }
    qInfo("%d compared, %d skipped, %d show the back of the subtracted ball", compared, skipped, backOfC);
    QVERIFY(backOfC > 50);
    QVERIFY(skipped < compared / 10);
}

void TestInspectReference::collisionsOfOverlappingBalls()
{
    // Two balls as one surface (no CSG) under parity, cut open by a plane (the kept span
    // starts inside them): where a span starts in one ball, the other ball's front face
    // (1 -> 2) or the first ball's back face is shown; a shown point collides iff it lies
    // inside the other ball (w = 2 is out under parity, so both kinds occur).
    const Ball a{{-0.3, 0.0, 0.0}, 0.7}, b{{0.35, 0.05, -0.1}, 0.6};
    const TriangleMesh meshA = ballMesh(a), meshB = ballMesh(b);
    const Ball inner[2] = {{a.center, inscribed(meshA, a.center)}, {b.center, inscribed(meshB, b.center)}};
    const Ball outer[2] = {a, b};
    const Scene scene = sceneOf({meshA, meshB});
    const Camera camera = viewOf(scene);
    TrimSettings settings;
    settings.rule = StaticRule::Parity;
    settings.highlight.collisions = true;
    settings.clip = ClipPlane{true, {0.0, 0.0, -1.0}, 0.05}; // keeps z <= 0.05, behind the eye's side
    const ReferenceResult r = ReferenceRenderer(scene).render(camera, kWidth, kHeight, settings);
    int flagged = 0, compared = 0, skipped = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const TrimPixel& p = r.trim.at(x, y);
            if (p.primitiveId < 0)
                continue;
            const PixelRay ray = pixelRay(camera, kWidth, kHeight, x, y);
            const glm::dvec3 point = ray.origin + double(p.viewDepth) * ray.direction;
            const int other = 1 - p.objectId;
            const double d = glm::length(point - outer[other].center);
            if (d > inner[other].radius - 1e-3 && d < outer[other].radius + 1e-3) {
                ++skipped;
                continue;
            }
            ++compared;
            const bool expected = d < inner[other].radius;
            QVERIFY2(p.collision == expected, qPrintable(QString("(%1, %2)").arg(x).arg(y)));
            flagged += expected ? 1 : 0;
        }
    }
    qInfo("%d flagged among %d compared, %d skipped", flagged, compared, skipped);
    QVERIFY(flagged > 100);
    QVERIFY(compared - flagged > 100);
}

void TestInspectReference::coplanarDuplicate()
{
    // One ball duplicated on itself: every covered pixel shows object 0's fragment (first
    // in walk order) in a coplanar group of exactly 2; the color is the group's palette
    // color (red for 2), not the trim palette.
    const TriangleMesh mesh = ballMesh({{0.0, 0.0, 0.0}, 1.0});
    const Scene scene = sceneOf({mesh, mesh});
    const Camera camera = viewOf(scene);
    TrimSettings settings;
    settings.rule = StaticRule::PositiveIndex;
    settings.highlight.coplanar = true;
    const ReferenceResult r = ReferenceRenderer(scene).render(camera, kWidth, kHeight, settings);
    int covered = 0;
    for (const TrimPixel& p : r.trim.pixels) {
        if (!p.covered())
            continue;
        ++covered;
        QCOMPARE(p.objectId, 0);
        QCOMPARE(int(p.coplanarCount), 2);
    }
    QVERIFY(covered > 1000);
    const std::uint8_t* centre = r.color.at(kWidth / 2, kHeight / 2);
    QVERIFY2(centre[0] > 2 * centre[1] && centre[0] > 2 * centre[2], "a group of 2 is red");
    // The highlight off: no counts.
    settings.highlight.coplanar = false;
    const ReferenceResult plain = ReferenceRenderer(scene).render(camera, kWidth, kHeight, settings);
    for (const TrimPixel& p : plain.trim.pixels)
        QCOMPARE(int(p.coplanarCount), 0);
}

QTEST_APPLESS_MAIN(TestInspectReference)
#include "tst_inspect_reference.moc"
