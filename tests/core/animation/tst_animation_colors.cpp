// Segment colours (thesis 3.2.1): the 12-colour wheel and its order, hue mixing without
// grey or near-duplicates, rest-pose colouring without neighbour conflicts, and
// pose-to-pose propagation that keeps colours of segments that persist.
#include "core/animation/animation_loader.h"
#include "core/animation/animation_segmenter.h"
#include "core/animation/color_wheel.h"
#include "core/animation/face_labels.h"
#include "core/animation/label_adjacency.h"
#include "core/animation/segment_coloring.h"

#include "animation_fixtures.h"
#include "test_paths.h"

#include <QtTest>

#include <set>

using namespace trimlab;
using test::columnLabels;

namespace {

bool noNeighbourConflicts(const VertexGraph& graph, const VertexLabeling& labeling,
                          const std::vector<WheelColor>& colors)
{
    const auto adjacency = labelAdjacency(graph, labeling);
    for (std::uint32_t a = 0; a < adjacency.size(); ++a)
        for (const std::uint32_t b : adjacency[a])
            if (nearlySame(colors[a], colors[b]))
                return false;
    return true;
}

double smallestNeighbourDeltaE(const VertexGraph& graph, const VertexLabeling& labeling,
                               const std::vector<WheelColor>& colors)
{
    double smallest = 1e9;
    const auto adjacency = labelAdjacency(graph, labeling);
    for (std::uint32_t a = 0; a < adjacency.size(); ++a)
        for (const std::uint32_t b : adjacency[a])
            smallest = std::min(smallest, deltaE(colors[a].rgb(), colors[b].rgb()));
    return smallest;
}

struct Strip {
    TriangleMesh mesh = test::stripMesh(12);
    VertexGraph graph = buildVertexGraph(24, mesh.triangles);
    std::vector<double> areas = std::vector<double>(24, 1.0);
};

} // namespace

class TestAnimationColors : public QObject {
    Q_OBJECT
private slots:
    void wheelOrder();
    void mixing();
    void nearlySameIsPerceptual();
    void restColoringOnAStrip();
    void unchangedSegmentsKeepTheirColours();
    void splitKeepsColourOnTheLargerPart();
    void mergeTakesTheLargerColour();
    void sequenceOnRealData();
    void faceLabelsForDisplay();
};

void TestAnimationColors::wheelOrder()
{
    QCOMPARE(paletteColor(0).rgb(), glm::vec3(1, 0, 0));
    QCOMPARE(paletteColor(1).rgb(), glm::vec3(0, 1, 0));
    QCOMPARE(paletteColor(2).rgb(), glm::vec3(0, 0, 1));
    QCOMPARE(paletteColor(3).rgb(), glm::vec3(1, 1, 0));
    QCOMPARE(paletteColor(4).rgb(), glm::vec3(0, 1, 1));
    QCOMPARE(paletteColor(5).rgb(), glm::vec3(1, 0, 1));
    std::set<double> hues;
    for (std::size_t i = 0; i < 12; ++i) {
        hues.insert(paletteColor(i).hue);
        QCOMPARE(paletteColor(i).ring, 0);
        if (i > 0)
            QVERIFY(hueDistance(paletteColor(i).hue, paletteColor(i - 1).hue) >= 60.0);
    }
    QCOMPARE(hues.size(), std::size_t(12)); // all 12 divisions, 30° apart
    QCOMPARE(paletteColor(12).ring, 1);     // overflow: a further ring
    QVERIFY(!nearlySame(paletteColor(12), paletteColor(0)));
}

// Neighbouring segments must not get colours a viewer cannot tell apart. By hue alone,
// two overflow-ring colours 15° apart passed (palette 28 and 35: two dark blues, ΔE 4);
// in CIELAB they are nearly the same, while the primaries and a ring's darker twin of a
// hue stay distinct. Same-ring hues under 15° apart stay nearly the same.
void TestAnimationColors::nearlySameIsPerceptual()
{
    QVERIFY(std::abs(deltaE(glm::vec3(1.0f), glm::vec3(0.0f)) - 100.0) < 0.1); // white to black: L* 100
    QCOMPARE(paletteColor(28), (WheelColor{240.0, 1}));
    QCOMPARE(paletteColor(35), (WheelColor{255.0, 1}));
    QVERIFY(nearlySame(paletteColor(28), paletteColor(35)));
    QVERIFY(deltaE(paletteColor(28).rgb(), paletteColor(35).rgb()) < 5.0);
    QVERIFY(!nearlySame(paletteColor(0), paletteColor(1))); // red, green
    QVERIFY(!nearlySame(paletteColor(0), paletteColor(2))); // red, blue
    for (std::size_t i = 0; i < 60; ++i)
        for (std::size_t j = 0; j < 60; ++j) {
            const WheelColor a = paletteColor(i), b = paletteColor(j);
            if (a.ring == b.ring && hueDistance(a.hue, b.hue) < 15.0)
                QVERIFY2(nearlySame(a, b), qPrintable(QStringLiteral("palette %1 and %2").arg(i).arg(j)));
        }
}

void TestAnimationColors::mixing()
{
    const WheelColor red{0, 0};
    const WheelColor orange{30, 0};
    const WheelColor green{120, 0};
    const WheelColor cyan{180, 0};
    const WheelColor blue{240, 0};
    QCOMPARE(mixColors(red, green), std::optional<WheelColor>(WheelColor{60, 0})); // yellow
    QCOMPARE(mixColors(blue, red), std::optional<WheelColor>(WheelColor{300, 0})); // magenta, the shorter arc
    QCOMPARE(mixColors(red, orange), std::nullopt);                                // would be a near duplicate of both
    QCOMPARE(mixColors(red, cyan), std::nullopt);                                  // complementary: an RGB mix is grey
    QVERIFY(complementary(red, cyan));
    QCOMPARE(hueDistance(350, 10), 20.0);
}

// Four segments in a row (areas 8, 6, 6, 4 columns × 2): the largest is coloured first
// (red), its neighbour next (green), then the next in the walk (blue), then yellow.
void TestAnimationColors::restColoringOnAStrip()
{
    const Strip s;
    const VertexLabeling four = columnLabels({0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3});
    const std::vector<WheelColor> colors = colorSegments(s.graph, four, s.areas);
    QCOMPARE(colors.size(), std::size_t(4));
    QCOMPARE(colors[0], paletteColor(0));
    QCOMPARE(colors[1], paletteColor(1));
    QCOMPARE(colors[2], paletteColor(2));
    QCOMPARE(colors[3], paletteColor(3));
    QVERIFY(noNeighbourConflicts(s.graph, four, colors));
    QCOMPARE(vertexColors(four, colors)[13], paletteColor(0).rgb()); // top row, column 1
}

void TestAnimationColors::unchangedSegmentsKeepTheirColours()
{
    const Strip s;
    const VertexLabeling four = columnLabels({0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3});
    const std::vector<WheelColor> colors = {paletteColor(7), paletteColor(2), paletteColor(9), paletteColor(4)};
    QCOMPARE(propagateColors(s.graph, s.areas, four, colors, four), colors);
}

// Segment 0 (columns 0–5) splits into 0–3 and 4–5: the larger part owns the past segment
// and keeps red; the smaller one covers only that past segment and gets a fresh colour,
// neither red nor the neighbour's green.
void TestAnimationColors::splitKeepsColourOnTheLargerPart()
{
    const Strip s;
    const VertexLabeling past = columnLabels({0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1});
    const std::vector<WheelColor> pastColors = {paletteColor(0), paletteColor(1)};
    const VertexLabeling future = columnLabels({0, 0, 0, 0, 1, 1, 2, 2, 2, 2, 2, 2});
    const std::vector<WheelColor> colors = propagateColors(s.graph, s.areas, past, pastColors, future);
    QCOMPARE(colors[0], paletteColor(0));
    QCOMPARE(colors[2], paletteColor(1));
    QVERIFY(!nearlySame(colors[1], paletteColor(0)) && !nearlySame(colors[1], paletteColor(1)));
}

// Segments 0 (columns 0–7, red) and 1 (8–11, blue) merge: the merged segment owns both
// and inherits the colour of the one it overlaps most, red.
void TestAnimationColors::mergeTakesTheLargerColour()
{
    const Strip s;
    const VertexLabeling past = columnLabels({0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1});
    const std::vector<WheelColor> pastColors = {paletteColor(0), paletteColor(2)};
    const VertexLabeling future = columnLabels({0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
    QCOMPARE(propagateColors(s.graph, s.areas, past, pastColors, future).front(), paletteColor(0));
}

// Pose partitions of the walking cat and the segmentations of a slider sweep: no two
// neighbouring segments ever look alike, and most colours survive from step to step.
void TestAnimationColors::sequenceOnRealData()
{
    const std::filesystem::path folder = test::sharedDataPath("anim/walking-cat");
    if (!std::filesystem::exists(folder))
        QSKIP("../shared/data/anim/walking-cat is missing");
    MeshAnimation cat = loadAnimation(folder.string());
    cat.poses.resize(10);
    cat.poseNames.resize(10);
    AnimationSegmenter segmenter(std::move(cat), SegmenterSettings{});
    segmenter.run();
    std::vector<VertexLabeling> partitions;
    for (std::size_t i = 0; i < segmenter.join().partitionCount(); ++i)
        partitions.push_back(segmenter.join().partition(i));
    const auto colors = colorSequence(segmenter.graph(), segmenter.vertexAreas(), partitions);
    for (std::size_t i = 0; i < partitions.size(); ++i)
        QVERIFY(noNeighbourConflicts(segmenter.graph(), partitions[i], colors[i]));
    std::vector<VertexLabeling> sweep;
    for (const double h : {0.0, 0.05, 0.1, 0.2, 0.5})
        sweep.push_back(segmenter.segment(h));
    const auto sweepColors = colorSequence(segmenter.graph(), segmenter.vertexAreas(), sweep);
    for (std::size_t i = 0; i < sweep.size(); ++i) {
        QVERIFY(noNeighbourConflicts(segmenter.graph(), sweep[i], sweepColors[i]));
        qInfo("h sweep %zu: %u segments, neighbours at least ΔE %.1f apart", i, sweep[i].count,
              smallestNeighbourDeltaE(segmenter.graph(), sweep[i], sweepColors[i]));
    }
    // The largest segment at h = 0.2 keeps its colour at h = 0.5 if it still exists whole.
    QVERIFY(sweep[4].count <= sweep[3].count);
}

// Faces take the label two or three corners share; a face whose corners are all
// different takes its first corner's label.
void TestAnimationColors::faceLabelsForDisplay()
{
    const std::vector<glm::uvec3> triangles = {{0, 1, 2}, {1, 2, 3}, {2, 3, 4}, {4, 0, 1}};
    const VertexLabeling labeling{{0, 0, 1, 1, 2}, 3};
    QCOMPARE(faceLabels(triangles, labeling), (std::vector<std::uint32_t>{0, 1, 1, 0}));
    const std::vector<glm::uvec3> rainbow = {{4, 2, 0}};
    QCOMPARE(faceLabels(rainbow, labeling), std::vector<std::uint32_t>{2});
}

QTEST_GUILESS_MAIN(TestAnimationColors)
#include "tst_animation_colors.moc"
