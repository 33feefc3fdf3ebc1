// Transparency / X-ray (core/trim/transparency.h, walkTrimLayers in trim_walk.h): the
// compositing on hand-made hit lists with every expected value derived by hand in the
// comments, and two identities of the CPU reference's images (Translucent with alpha 1
// and Opaque without ghosts both equal the image without transparency).
#include "core/catalog/demo_scenes.h"
#include "core/trim/reference_renderer.h"
#include "core/trim/transparency.h"
#include "core/trim/trim_shading.h"
#include "core/trim/trim_walk.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace trimlab;

namespace {

constexpr int F = 1;
constexpr int B = -1;
const glm::dvec3 kBlack{0.0};
const glm::dvec3 kBg{0.1, 0.2, 0.3};

RayHit hit(double t, int facing, int primitiveId)
{
    return {t, 0, primitiveId, facing, 0.25, 0.5};
}

TransparencySettings translucent(double layerAlpha, double ghostAlpha = 0.0, double density = 0.0)
{
    TransparencySettings s;
    s.enabled = true;
    s.display = TrimDisplay::Translucent;
    s.layerAlpha = layerAlpha;
    s.ghostAlpha = ghostAlpha;
    s.density = density;
    return s;
}

// A distinct color per primitive id, so every layer's contribution is traceable.
glm::dvec3 colorOf(int primitiveId)
{
    return {0.1 * (primitiveId % 10), 0.5, 1.0 - 0.05 * primitiveId};
}

// The walk's layers of `hits` (any order: sorted here, as every backend sorts) as X-ray
// fragments, facing the viewer (cosine 1).
std::vector<XrayFragment> walkedFragments(std::vector<RayHit> hits, const TrimSettings& settings)
{
    std::sort(hits.begin(), hits.end(), walkOrder);
    const KeptSpan span{false, 0.1, 100.0, true};
    const TrimWalk walk = walkTrimRay(hits, span, settings);
    std::vector<WalkLayer> layers;
    walkTrimLayers(hits, walk, settings, layers);
    std::vector<XrayFragment> fragments;
    for (const WalkLayer& layer : layers) {
        const RayHit& h = hits[layer.index];
        fragments.push_back({h.t, layer.boundary, layer.interiorBefore, colorOf(h.primitiveId), 1.0});
    }
    return fragments;
}

bool near(const glm::dvec3& a, const glm::dvec3& b)
{
    return glm::all(glm::lessThan(glm::abs(a - b), glm::dvec3(1e-12)));
}

QByteArray text(const glm::dvec3& c)
{
    return QByteArray::number(c.r, 'g', 17) + ", " + QByteArray::number(c.g, 'g', 17) + ", " +
           QByteArray::number(c.b, 'g', 17);
}

#define COMPARE_COLOR(actual, expected)                                                                                \
    QVERIFY2(near(actual, expected), (text(actual) + " != " + text(expected)).constData())

} // namespace

class TestTransparency : public QObject {
    Q_OBJECT
private slots:
    void oneLayerIsAnExactMix();
    void layersOfTheWalk();
    void inputOrderDoesNotMatter();
    void densityAttenuatesByBeerLambert();
    void fresnelGrowsAlphaAtGrazingAngles();
    void opaqueKeepsTheShownColorWithoutGhosts();
    void opaqueShowsGhostsInFront();
    void capsAreTheFirstLayer();
    void compositingStopsBelowTheThreshold();
    void badValuesAreClamped();
    void referenceIdentities();
};

void TestTransparency::oneLayerIsAnExactMix()
{
    const XrayFragment layer{2.0, true, false, {1.0, 0.5, 0.25}, 1.0};
    // C = a·c + (1 − a)·bg with a = 0.4.
    COMPARE_COLOR(compositeXray(translucent(0.4), 0.0, std::nullopt, {&layer, 1}, kBg), 0.4 * layer.color + 0.6 * kBg);
}

void TestTransparency::layersOfTheWalk()
{
    // Alternating border; F F B B at t = 1..4. Windings from the far side: 0 | 1 | 2 | 1 | 0;
    // interior iff w mod 4 in {1, 2}: out | in | in | in | out. Boundaries: the first F and
    // the last B; the inner F and B are removed fragments (ghosts).
    TrimSettings settings;
    const std::vector<XrayFragment> f =
        walkedFragments({hit(1, F, 0), hit(2, F, 1), hit(3, B, 2), hit(4, B, 3)}, settings);
    QCOMPARE(f.size(), std::size_t(4));
    const bool boundary[] = {true, false, false, true};
    const bool interiorBefore[] = {false, true, true, true};
    for (std::size_t i = 0; i < 4; ++i) {
        QCOMPARE(f[i].boundary, boundary[i]);
        QCOMPARE(f[i].interiorBefore, interiorBefore[i]);
    }
    // With trimming off every hit is a boundary and nothing is interior.
    settings.trimEnabled = false;
    for (const XrayFragment& x : walkedFragments({hit(1, F, 0), hit(2, F, 1), hit(3, B, 2), hit(4, B, 3)}, settings))
        QVERIFY(x.boundary && !x.interiorBefore);
}

void TestTransparency::inputOrderDoesNotMatter()
{
    // A ball (F at 2, B at 5) seen with layer alpha a and ghosts hidden:
    // C = a·c0 + (1 − a)·a·c1 + (1 − a)²·bg, whatever the order the hits arrive in.
    TrimSettings settings;
    const TransparencySettings xray = translucent(0.3);
    const glm::dvec3 expected = 0.3 * colorOf(0) + 0.7 * 0.3 * colorOf(1) + 0.49 * kBg;
    const std::vector<XrayFragment> inOrder = walkedFragments({hit(2, F, 0), hit(5, B, 1)}, settings);
    const std::vector<XrayFragment> reversed = walkedFragments({hit(5, B, 1), hit(2, F, 0)}, settings);
    COMPARE_COLOR(compositeXray(xray, 0.1, std::nullopt, inOrder, kBg), expected);
    COMPARE_COLOR(compositeXray(xray, 0.1, std::nullopt, reversed, kBg), expected);
}

void TestTransparency::densityAttenuatesByBeerLambert()
{
    // The same ball with density ρ = 0.7: the interval [2, 5] inside attenuates by e^(−3ρ);
    // the intervals in front of and behind the ball are outside and attenuate nothing.
    TrimSettings settings;
    const double rho = 0.7;
    const double e = std::exp(-3.0 * rho);
    const std::vector<XrayFragment> f = walkedFragments({hit(2, F, 0), hit(5, B, 1)}, settings);
    const glm::dvec3 expected = 0.3 * colorOf(0) + 0.7 * e * 0.3 * colorOf(1) + 0.7 * e * 0.7 * kBg;
    COMPARE_COLOR(compositeXray(translucent(0.3, 0.0, rho), 0.1, std::nullopt, f, kBg), expected);
    // With invisible layers only the absorption remains: exactly e^(−ρ t) of the background.
    COMPARE_COLOR(compositeXray(translucent(0.0, 0.0, rho), 0.1, std::nullopt, f, kBg), e * kBg);
    // A span starting inside the solid (the eye or a clip plane inside): [0.5, 2] counts.
    std::vector<XrayFragment> inside = {{2.0, true, true, colorOf(0), 1.0}};
    COMPARE_COLOR(compositeXray(translucent(0.0, 0.0, rho), 0.5, std::nullopt, inside, kBg),
                  std::exp(-1.5 * rho) * kBg);
}

void TestTransparency::fresnelGrowsAlphaAtGrazingAngles()
{
    // α' = α + (1 − α)(1 − |n·v|)^p.
    QCOMPARE(fresnelAlpha(0.2, 1.0, 5.0), 0.2);
    QCOMPARE(fresnelAlpha(0.2, 0.0, 5.0), 1.0);
    QCOMPARE(fresnelAlpha(0.2, -0.5, 5.0), 0.2 + 0.8 * std::pow(0.5, 5.0));
    QVERIFY(fresnelAlpha(0.2, 0.3, 2.0) > fresnelAlpha(0.2, 0.6, 2.0));
    QVERIFY(fresnelAlpha(0.2, 0.6, 2.0) > fresnelAlpha(0.2, 0.9, 2.0));
    QCOMPARE(fresnelAlpha(0.2, 0.0, 0.0), 0.2); // off
    QCOMPARE(fresnelAlpha(0.0, 0.0, 5.0), 0.0); // hidden stays hidden
    // In the compositing: a grazing layer (cosine 0.1) with p = 1 takes α' = 0.2 + 0.8·0.9.
    TransparencySettings s = translucent(0.2);
    s.fresnelExponent = 1.0;
    const XrayFragment grazing{2.0, true, false, {1.0, 1.0, 1.0}, 0.1};
    const double a = 0.2 + 0.8 * 0.9;
    COMPARE_COLOR(compositeXray(s, 0.0, std::nullopt, {&grazing, 1}, kBg), a * grazing.color + (1.0 - a) * kBg);
}

void TestTransparency::opaqueKeepsTheShownColorWithoutGhosts()
{
    TransparencySettings s = translucent(0.3, 0.5);
    s.display = TrimDisplay::Opaque;
    // The shown (first boundary) fragment with nothing removed in front: its color alone,
    // whatever lies behind it.
    TrimSettings settings;
    const std::vector<XrayFragment> f =
        walkedFragments({hit(2, F, 0), hit(3, F, 1), hit(4, B, 2), hit(5, B, 3)}, settings);
    COMPARE_COLOR(compositeXray(s, 0.1, std::nullopt, f, kBg), colorOf(0));
}

void TestTransparency::opaqueShowsGhostsInFront()
{
    // Positive index; B at 1 then F F at 2, 3, B at 4. Windings from the far side:
    // 0 | -1 | 0 | 1 | 0 -> out | out | out | in | out. The first two hits are removed
    // (ghosts), the F at 3 is the shown boundary: C = g·c0 + (1−g)·g·c1 + (1−g)²·c2.
    TrimSettings settings;
    settings.rule = StaticRule::PositiveIndex;
    TransparencySettings s = translucent(0.3, 0.25);
    s.display = TrimDisplay::Opaque;
    const std::vector<XrayFragment> f =
        walkedFragments({hit(1, B, 0), hit(2, F, 1), hit(3, F, 2), hit(4, B, 3)}, settings);
    const glm::dvec3 expected = 0.25 * colorOf(0) + 0.75 * 0.25 * colorOf(1) + 0.75 * 0.75 * colorOf(2);
    COMPARE_COLOR(compositeXray(s, 0.1, std::nullopt, f, kBg), expected);
}

void TestTransparency::capsAreTheFirstLayer()
{
    const XrayCap cap{{0.9, 0.8, 0.7}, 1.0};
    const XrayFragment back{3.0, true, true, {0.2, 0.4, 0.6}, 1.0};
    TransparencySettings s = translucent(0.5);
    // Translucent: C = a·cap + (1 − a)·a·back + (1 − a)²·bg.
    COMPARE_COLOR(compositeXray(s, 1.0, cap, {&back, 1}, kBg), 0.5 * cap.color + 0.25 * back.color + 0.25 * kBg);
    // Opaque: the cap as without transparency.
    s.display = TrimDisplay::Opaque;
    COMPARE_COLOR(compositeXray(s, 1.0, cap, {&back, 1}, kBg), cap.color);
}

void TestTransparency::compositingStopsBelowTheThreshold()
{
    // Alpha 1/2: after 9 layers T = 2^-9 (not below 1/512), after 10 T = 2^-10 < 1/512,
    // so the 11th and 12th layers (white) contribute nothing; the background still gets
    // the remaining T (step 4 of the sequence).
    std::vector<XrayFragment> f;
    for (int i = 0; i < 12; ++i)
        f.push_back({1.0 + i, true, false, i < 10 ? kBlack : glm::dvec3(1.0), 1.0});
    COMPARE_COLOR(compositeXray(translucent(0.5), 0.0, std::nullopt, f, kBlack), kBlack);
    COMPARE_COLOR(compositeXray(translucent(0.5), 0.0, std::nullopt, f, glm::dvec3(1.0)),
                  glm::dvec3(std::ldexp(1.0, -10)));
    // With nine black layers the tenth (white) one still counts: 2^-9 · 1/2 + 2^-10 · bg(0).
    f[9].color = glm::dvec3(1.0);
    COMPARE_COLOR(compositeXray(translucent(0.5), 0.0, std::nullopt, f, kBlack), glm::dvec3(std::ldexp(1.0, -10)));
}

void TestTransparency::badValuesAreClamped()
{
    const XrayFragment layer{2.0, true, true, {1.0, 1.0, 1.0}, 0.5};
    TransparencySettings s = translucent(7.0, -1.0, -3.0); // alpha > 1, ghosts < 0, density < 0
    s.fresnelExponent = std::nan("");
    COMPARE_COLOR(compositeXray(s, 0.0, std::nullopt, {&layer, 1}, kBg), layer.color);
    s = translucent(std::nan(""), 0.0, std::numeric_limits<double>::infinity());
    const glm::dvec3 c = compositeXray(s, 0.0, std::nullopt, {&layer, 1}, kBg);
    QVERIFY(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b));
    COMPARE_COLOR(c, kBg);
}

void TestTransparency::referenceIdentities()
{
    // The pushed sphere has removed fragments in front of its shown points, so the plain
    // image differs from Opaque with ghosts; Translucent with alpha 1 (ghosts hidden) and
    // Opaque with ghosts hidden must both reproduce the plain image byte for byte.
    const Scene scene = *makeDemoScene("pushed-sphere");
    const ReferenceRenderer reference(scene);
    const Camera camera = fitCamera(scene.worldBounds(), 64.0 / 48.0);
    TrimSettings settings;
    const ReferenceResult plain = reference.render(camera, 64, 48, settings);
    settings.transparency = translucent(1.0, 0.0, 0.0);
    QVERIFY(reference.render(camera, 64, 48, settings).color.rgba == plain.color.rgba);
    settings.transparency.display = TrimDisplay::Opaque;
    settings.transparency.layerAlpha = 0.3;
    QVERIFY(reference.render(camera, 64, 48, settings).color.rgba == plain.color.rgba);
    settings.transparency.ghostAlpha = 0.5;
    const ReferenceResult ghosts = reference.render(camera, 64, 48, settings);
    QVERIFY(ghosts.color.rgba != plain.color.rgba);
    // The id image never changes.
    for (std::size_t i = 0; i < plain.trim.pixels.size(); ++i)
        QCOMPARE(ghosts.trim.pixels[i].primitiveId, plain.trim.pixels[i].primitiveId);
}

QTEST_APPLESS_MAIN(TestTransparency)
#include "tst_transparency.moc"
