// The over-segmentation (thesis Definitions 3.1–3.3, Algorithm 3.1) on hand-made strips
// with known answers, against an independent union-find oracle, independence of the
// joining order (3.2.6), and the incremental join (prefix levels, replacing a partition).
#include "core/animation/over_segmentation.h"
#include "core/animation/pose_join.h"

#include "animation_fixtures.h"

#include <QtTest>

#include <numeric>
#include <random>

using namespace trimlab;
using test::columnLabels;

namespace {

std::shared_ptr<const VertexGraph> stripGraph(unsigned columns)
{
    const TriangleMesh mesh = test::stripMesh(columns);
    return std::make_shared<const VertexGraph>(buildVertexGraph(mesh.positions.size(), mesh.triangles));
}

// The oracle: union-find over every edge whose endpoints have equal CAVs.
VertexLabeling unionFindClasses(const VertexGraph& graph, const std::vector<VertexLabeling>& partitions)
{
    std::vector<std::uint32_t> parent(graph.vertexCount());
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](std::uint32_t v) {
        while (parent[v] != v)
            v = parent[v] = parent[parent[v]];
        return v;
    };
    for (std::uint32_t u = 0; u < graph.vertexCount(); ++u) {
        for (const std::uint32_t v : graph.neighborsOf(u)) {
            bool same = true;
            for (const VertexLabeling& p : partitions)
                same = same && p.labels[u] == p.labels[v];
            if (same)
                parent[find(u)] = find(v);
        }
    }
    std::vector<std::uint32_t> roots(graph.vertexCount());
    for (std::uint32_t v = 0; v < graph.vertexCount(); ++v)
        roots[v] = find(v);
    return canonicalLabeling(roots);
}

// A random labeling with few labels, so that equal-CAV neighbours are common.
VertexLabeling randomLabels(std::size_t count, std::uint32_t labels, std::mt19937& random)
{
    std::uniform_int_distribution<std::uint32_t> pick(0, labels - 1);
    VertexLabeling l;
    for (std::size_t v = 0; v < count; ++v)
        l.labels.push_back(pick(random));
    l.count = labels;
    return l;
}

} // namespace

class TestAnimationOverSegmentation : public QObject {
    Q_OBJECT
private slots:
    void threePoseClusterings();
    void sameCavApartIsTwoSegments();
    void noPartitionsGiveComponents();
    void matchesUnionFindOracle();
    void joiningOrderDoesNotMatter();
    void prefixLevelsAndReplace();
};

// The situation of thesis Figure 3.3 (its picture is not part of our text copy; this
// rebuilds it): three pose clusterings of a 10-column strip,
//   C1: columns 0–4 | 5–9,   C2: 0–3 | 4–9,   C3: 0–6 | 7–9,
// give the CAVs 000 (0–3), 010 (4), 110 (5–6), 111 (7–9): four segments. (The cleaning
// test continues this example.)
void TestAnimationOverSegmentation::threePoseClusterings()
{
    const auto graph = stripGraph(10);
    const std::vector<VertexLabeling> partitions = {columnLabels({0, 0, 0, 0, 0, 1, 1, 1, 1, 1}),
                                                    columnLabels({0, 0, 0, 0, 1, 1, 1, 1, 1, 1}),
                                                    columnLabels({0, 0, 0, 0, 0, 0, 0, 1, 1, 1})};
    const VertexLabeling os = overSegmentation(*graph, partitions);
    QCOMPARE(os, columnLabels({0, 0, 0, 0, 1, 2, 2, 3, 3, 3}));
}

// Columns 5 and 7 share the CAV (1, 1, 0) but column 6 (1, 1, 1) separates them: two
// segments (Definition 3.3 takes connected classes, not equal CAVs alone).
void TestAnimationOverSegmentation::sameCavApartIsTwoSegments()
{
    const auto graph = stripGraph(10);
    const std::vector<VertexLabeling> partitions = {columnLabels({0, 0, 0, 0, 0, 1, 1, 1, 1, 1}),
                                                    columnLabels({0, 0, 0, 0, 1, 1, 1, 1, 1, 1}),
                                                    columnLabels({0, 0, 0, 0, 0, 0, 1, 0, 0, 0})};
    const VertexLabeling os = overSegmentation(*graph, partitions);
    QCOMPARE(os, columnLabels({0, 0, 0, 0, 1, 2, 3, 4, 4, 4}));
}

void TestAnimationOverSegmentation::noPartitionsGiveComponents()
{
    const auto graph = stripGraph(4);
    QCOMPARE(overSegmentation(*graph, {}), columnLabels({0, 0, 0, 0}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             (void)overSegmentation(*graph, std::vector<VertexLabeling>{VertexLabeling{}}));
}

void TestAnimationOverSegmentation::matchesUnionFindOracle()
{
    std::mt19937 random(7);
    const auto graph = stripGraph(40);
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<VertexLabeling> partitions;
        for (int p = 0; p < 1 + trial % 5; ++p)
            partitions.push_back(randomLabels(graph->vertexCount(), 2, random));
        QCOMPARE(overSegmentation(*graph, partitions), unionFindClasses(*graph, partitions));
    }
}

// "The over-segmentation result does not depend on the joining order" (3.2.6).
void TestAnimationOverSegmentation::joiningOrderDoesNotMatter()
{
    std::mt19937 random(11);
    const auto graph = stripGraph(30);
    std::vector<VertexLabeling> partitions;
    for (int p = 0; p < 4; ++p)
        partitions.push_back(randomLabels(graph->vertexCount(), 2, random));
    const VertexLabeling forward = overSegmentation(*graph, partitions);
    std::reverse(partitions.begin(), partitions.end());
    QCOMPARE(overSegmentation(*graph, partitions), forward);
    std::rotate(partitions.begin(), partitions.begin() + 1, partitions.end());
    QCOMPARE(overSegmentation(*graph, partitions), forward);
}

void TestAnimationOverSegmentation::prefixLevelsAndReplace()
{
    std::mt19937 random(3);
    const auto graph = stripGraph(25);
    std::vector<VertexLabeling> partitions;
    PoseJoin join(graph);
    for (int p = 0; p < 5; ++p) {
        partitions.push_back(randomLabels(graph->vertexCount(), 3, random));
        join.append(partitions.back());
    }
    for (std::size_t i = 0; i <= partitions.size(); ++i)
        QCOMPARE(join.level(i), overSegmentation(*graph, std::span(partitions).first(i)));
    partitions[2] = randomLabels(graph->vertexCount(), 3, random);
    join.replace(2, partitions[2]);
    for (std::size_t i = 0; i <= partitions.size(); ++i)
        QCOMPARE(join.level(i), overSegmentation(*graph, std::span(partitions).first(i)));
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, join.replace(9, partitions[0]));
}

QTEST_GUILESS_MAIN(TestAnimationOverSegmentation)
#include "tst_animation_oversegmentation.moc"
