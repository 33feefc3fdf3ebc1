// The temporal-coherence measure (core/trim/temporal_coherence.h) on a hand-built
// animation whose answer is known: a unit ball A that never moves and a small ball B
// moving along the view axis.
// - B entering A through A's front wall sweeps the wall: the classes beside the wall flip
//   under every rule there (swept flips); parity keeps the wall (no visible flip), the
//   alternating border and the confluent rule trim it.
// - B moving inside A towards the eye sweeps nothing of A, so no static rule flips
//   anything; the thesis's walk decides one class per interval between current fragments
//   (Algorithm 8.13), and the interval in front of A's back wall is decided just behind
//   B's back, in the volume B left: the confluent and subtractive rules trim A's back wall
//   behind B although no surface crossed it (unswept flips); the additive rule does not.
// The classifier that carries the characterization from frame to frame
// (frame_sequence_classifier.h) shows what DynamicReferenceRenderer shows for the whole
// chain, and the first frame what ReferenceRenderer shows.
#include "core/mesh/triangle_mesh.h"
#include "core/scene/shape_generators.h"
#include "core/trim/dynamic_chain.h"
#include "core/trim/dynamic_reference_renderer.h"
#include "core/trim/reference_renderer.h"
#include "core/trim/temporal_coherence.h"

#include <QtTest>

using namespace trimlab;

namespace {

constexpr int kSize = 40;

struct TwoBalls {
    std::vector<glm::uvec3> triangles;
    std::vector<glm::vec3> ballA;
    std::vector<glm::vec3> ballB; ///< centred at the origin
    std::vector<glm::vec3> frame(float bZ) const
    {
        std::vector<glm::vec3> positions = ballA;
        for (const glm::vec3& p : ballB)
            positions.push_back(p + glm::vec3(0.0f, 0.0f, bZ));
        return positions;
    }
};

TwoBalls twoBalls()
{
    TwoBalls balls;
    TriangleMesh mesh = makeIcosphere(glm::dvec3(0.0), 1.0, 3);
    balls.ballA = mesh.positions;
    const TriangleMesh b = makeIcosphere(glm::dvec3(0.0), 0.3, 2);
    balls.ballB = b.positions;
    appendMesh(mesh, b);
    balls.triangles = mesh.triangles;
    return balls;
}

// Looking down −z at the balls from `eyeZ` (outside A at 5, inside A at 0.85).
Camera cameraAt(double eyeZ)
{
    Camera camera;
    camera.eye = glm::dvec3(0.0, 0.0, eyeZ);
    camera.target = glm::dvec3(0.0, 0.0, -1.0);
    camera.fovyDegrees = eyeZ > 1.0 ? 30.0 : 90.0;
    Bounds bounds;
    bounds.extend(glm::dvec3(-1.5, -1.5, -1.5));
    bounds.extend(glm::dvec3(1.5, 1.5, 2.5));
    return withDepthRange(camera, bounds);
}

SequenceRule staticRule(StaticRule rule)
{
    SequenceRule r;
    r.staticRule = rule;
    return r;
}

SequenceRule dynamicRule(DynamicRule rule, SequenceReference reference)
{
    SequenceRule r;
    r.dynamicRule = rule;
    r.reference = reference;
    return r;
}

// The counts of the pair (B at z0, B at z1) under `rule`.
CoherenceCounts pairCounts(const TwoBalls& balls, float z0, float z1, SequenceRule rule)
{
    FrameSequenceClassifier classifier(balls.triangles, cameraAt(5.0), kSize, kSize, rule, 2);
    const FrameFragments before = classifier.next(balls.frame(z0));
    const FrameFragments after = classifier.next(balls.frame(z1));
    return compareFrames(before, after, 1e-6);
}

// The first kept fragment of every pixel, as (triangle, object 0) or empty.
std::vector<std::int32_t> shownTriangles(const FrameFragments& frame)
{
    std::vector<std::int32_t> shown;
    for (const auto& fragments : frame.pixels) {
        std::int32_t triangle = -1;
        for (const ClassifiedFragment& f : fragments)
            if (f.kept()) {
                triangle = std::int32_t(f.triangle);
                break;
            }
        shown.push_back(triangle);
    }
    return shown;
}

std::vector<std::int32_t> shownTriangles(const TrimImage& image)
{
    std::vector<std::int32_t> shown;
    for (const TrimPixel& p : image.pixels)
        shown.push_back(p.primitiveId);
    return shown;
}

std::size_t differingPixels(const std::vector<std::int32_t>& a, const std::vector<std::int32_t>& b)
{
    std::size_t count = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        count += a[i] != b[i] ? 1 : 0;
    return count;
}

} // namespace

class TestTemporalCoherence : public QObject {
    Q_OBJECT
private slots:
    void enteringBallFlipsTheSweptWall();
    void ballMovingInsideFlipsOnlyUnderTheWalk();
    void carriedCharacterizationMatchesTheReference();
    void fragmentsAreMatchedByTriangleAndDepth();
};

void TestTemporalCoherence::enteringBallFlipsTheSweptWall()
{
    const TwoBalls balls = twoBalls();
    const CoherenceCounts parity = pairCounts(balls, 1.7f, 1.0f, staticRule(StaticRule::Parity));
    QVERIFY(parity.unmovedPixels > 100);
    QVERIFY(parity.flippedPixels > 0);
    QCOMPARE(parity.trimFlippedPixels, std::size_t(0));
    QCOMPARE(parity.unsweptFlippedPixels, std::size_t(0));
    const CoherenceCounts alternating = pairCounts(balls, 1.7f, 1.0f, staticRule(StaticRule::AlternatingBorder));
    QCOMPARE(alternating.flippedPixels, parity.flippedPixels); // the same swept pixels
    QCOMPARE(alternating.trimFlippedPixels, parity.flippedPixels);
    QCOMPARE(alternating.unsweptFlippedPixels, std::size_t(0));
    for (SequenceReference reference : {SequenceReference::First, SequenceReference::Previous}) {
        const CoherenceCounts confluent = pairCounts(balls, 1.7f, 1.0f, dynamicRule(DynamicRule::Confluent, reference));
        QCOMPARE(confluent.unmovedPixels, parity.unmovedPixels);
        QCOMPARE(confluent.trimFlippedPixels, parity.flippedPixels);
        QCOMPARE(confluent.unsweptFlippedPixels, std::size_t(0));
    }
}

void TestTemporalCoherence::ballMovingInsideFlipsOnlyUnderTheWalk()
{
    const TwoBalls balls = twoBalls();
    for (StaticRule rule : {StaticRule::Parity, StaticRule::PositiveIndex, StaticRule::AlternatingBorder}) {
        const CoherenceCounts counts = pairCounts(balls, -0.4f, 0.0f, staticRule(rule));
        QVERIFY(counts.unmovedPixels > 100);
        QCOMPARE(counts.flippedPixels, std::size_t(0));
    }
    const CoherenceCounts additive =
        pairCounts(balls, -0.4f, 0.0f, dynamicRule(DynamicRule::ConstructiveAdditive, SequenceReference::Previous));
    QCOMPARE(additive.flippedPixels, std::size_t(0));
    std::size_t confluentFlips = 0;
    for (DynamicRule rule : {DynamicRule::Confluent, DynamicRule::ConstructiveSubtractive}) {
        const CoherenceCounts counts = pairCounts(balls, -0.4f, 0.0f, dynamicRule(rule, SequenceReference::Previous));
        QVERIFY(counts.unsweptFlippedPixels > 10);
        QCOMPARE(counts.trimFlippedPixels, counts.unsweptFlippedPixels); // A's back wall, trimmed
        QCOMPARE(counts.flippedPixels, counts.unsweptFlippedPixels);
        confluentFlips = counts.flippedPixels;
    }
    // Only behind B: B covers fewer pixels than a third of the image here.
    QVERIFY(confluentFlips < std::size_t(kSize * kSize / 3));
}

void TestTemporalCoherence::carriedCharacterizationMatchesTheReference()
{
    const TwoBalls balls = twoBalls();
    const Camera camera = cameraAt(0.85); // inside A: B and A's back wall are seen
    const std::vector<float> zs = {-0.45f, -0.35f, -0.25f, -0.1f};
    for (DynamicRule rule : {DynamicRule::Confluent, DynamicRule::ConstructiveSubtractive}) {
        for (SequenceReference reference : {SequenceReference::First, SequenceReference::Previous}) {
            FrameSequenceClassifier classifier(balls.triangles, camera, kSize, kSize, dynamicRule(rule, reference), 2);
            std::vector<std::vector<glm::vec3>> frames;
            std::size_t differing = 0;
            for (std::size_t k = 0; k < zs.size(); ++k) {
                frames.push_back(balls.frame(zs[k]));
                const FrameFragments fragments = classifier.next(frames.back());
                TrimImage expected;
                if (k == 0) {
                    Scene scene;
                    scene.objects.emplace_back();
                    scene.objects.back().mesh = {frames[0], balls.triangles};
                    expected = ReferenceRenderer(scene).render(camera, kSize, kSize, TrimSettings{}, 2).trim;
                } else {
                    const std::vector<std::vector<glm::vec3>> chainFrames =
                        reference == SequenceReference::Previous ? frames : std::vector{frames.front(), frames.back()};
                    const DynamicChain chain =
                        makeDynamicChain(balls.triangles, chainFrames, std::vector(chainFrames.size() - 1, rule),
                                         StaticRule::AlternatingBorder);
                    const TrimImage ids = DynamicReferenceRenderer(chain).render(camera, kSize, kSize, {}, 2).trim;
                    expected = withMeshIds(ids, chain.levels.back().frame);
                }
                differing += differingPixels(shownTriangles(fragments), shownTriangles(expected));
                if (k + 1 == zs.size()) {
                    // The history matters: the last frame differs from its static trim.
                    FrameSequenceClassifier still(balls.triangles, camera, kSize, kSize,
                                                  staticRule(StaticRule::AlternatingBorder), 2);
                    const std::size_t againstStatic =
                        differingPixels(shownTriangles(fragments), shownTriangles(still.next(frames.back())));
                    QVERIFY(againstStatic > 10);
                }
            }
            QCOMPARE(differing, std::size_t(0));
        }
    }
}

void TestTemporalCoherence::fragmentsAreMatchedByTriangleAndDepth()
{
    ClassifiedFragment wall;
    wall.triangle = 7;
    wall.depth = 2.0;
    wall.windingFront = 0;
    wall.windingBack = 1;
    wall.interiorBack = true;
    ClassifiedFragment inside = wall; // B arrived around it: both sides inside
    inside.windingFront = 1;
    inside.windingBack = 2;
    inside.interiorFront = true;
    const std::vector<ClassifiedFragment> before = {wall};
    PixelCoherence p = comparePixel(before, std::vector{inside}, 1e-3);
    QVERIFY(p.unmoved && p.flipped && p.trimFlipped && !p.unsweptFlipped);
    inside.depth = 2.01; // moved beyond the tolerance: not the same fragment
    p = comparePixel(before, std::vector{inside}, 1e-3);
    QVERIFY(!p.unmoved && !p.flipped);
    ClassifiedFragment other = wall; // another triangle at the same depth
    other.triangle = 8;
    other.interiorBack = false;
    p = comparePixel(before, std::vector{other}, 1e-3);
    QVERIFY(!p.unmoved);
    ClassifiedFragment trimmed = wall; // same windings, class changed: unswept
    trimmed.interiorBack = false;
    p = comparePixel(before, std::vector{trimmed}, 1e-3);
    QVERIFY(p.unmoved && p.flipped && p.trimFlipped && p.unsweptFlipped);
}

QTEST_APPLESS_MAIN(TestTemporalCoherence)
#include "tst_temporal_coherence.moc"
