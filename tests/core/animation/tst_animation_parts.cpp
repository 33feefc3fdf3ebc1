// The pieces of animation loading and segmentation on small strips: seeded region growing
// and the pose partition built on it, the topology check between poses, glTF animation
// clips, the skin kept for welded vertices, segment colours, and the segmentation record
// with the file it is written to.
#include "core/animation/animation_skin.h"
#include "core/animation/gltf_animation_clip.h"
#include "core/animation/pose_partition.h"
#include "core/animation/pose_topology.h"
#include "core/animation/seeded_region_growing.h"
#include "core/animation/segment_colors.h"
#include "core/animation/segmentation_record.h"

#include "core/animation/animation_segmenter.h"
#include "core/image/packed_rgba8.h"
#include "core/io/gltf_builder.h"
#include "core/mesh/mesh_load_error.h"
#include "tests/core/mesh/mesh_error_text.h"

#include "animation_fixtures.h"

#include <QTemporaryDir>
#include <QtTest>

#include <nlohmann/json.hpp>

#include <fstream>
#include <functional>
#include <sstream>

using namespace trimlab;
using namespace trimlab::test;

namespace {

constexpr unsigned kColumns = 10;

// One feature value per vertex of the strip: its column's x.
std::vector<double> columnFeature()
{
    const TriangleMesh strip = stripMesh(kColumns);
    std::vector<double> values;
    for (const glm::vec3& p : strip.positions)
        values.push_back(p.x);
    return values;
}

// A strip of 31 columns whose right half bends up over five poses.
MeshAnimation bendingStrip()
{
    const TriangleMesh strip = stripMesh(31);
    std::vector<std::vector<glm::vec3>> poses;
    for (int i = 1; i <= 5; ++i) {
        poses.push_back(strip.positions);
        for (glm::vec3& p : poses.back())
            p.z = p.x > 15.0f ? 0.1f * float(i) * (p.x - 15.0f) : 0.0f;
    }
    return animationOf(strip, poses);
}

} // namespace

class TestAnimationParts : public QObject {
    Q_OBJECT

private slots:
    // Two seeds at the strip's ends with the column x as feature: each vertex joins the
    // seed whose feature is nearer, the domain limits the growth, and Lloyd steps keep a
    // balanced split.
    void regionsGrowFromTheirSeeds()
    {
        const TriangleMesh strip = stripMesh(kColumns);
        const VertexGraph graph = buildVertexGraph(strip.vertexCount(), strip.triangles);
        const std::vector<double> values = columnFeature();
        const FeatureView feature{values, 1};
        QCOMPARE(feature.distance(3, std::vector<double>{1.0}), 2.0);

        const std::vector<std::uint32_t> seeds = {0, kColumns - 1};
        const std::vector<std::uint32_t> regions =
            growRegions(graph, feature, seeds, std::vector<double>{0.0, double(kColumns - 1)});
        for (std::size_t v = 0; v < strip.vertexCount(); ++v)
            QCOMPARE(regions[v], std::uint32_t(values[v] < 4.5 ? 0 : 1));

        std::vector<std::uint32_t> domainLabels(strip.vertexCount(), 0);
        domainLabels[5] = domainLabels[kColumns + 5] = 1; // column 5 cuts the strip
        const std::vector<std::uint32_t> cut =
            growRegions(graph, feature, std::vector<std::uint32_t>{0}, std::vector<double>{0.0}, {domainLabels, 0});
        QCOMPARE(cut[4], std::uint32_t(0));
        QCOMPARE(cut[5], kNoRegion);
        QCOMPARE(cut[9], kNoRegion); // beyond the cut: unreachable

        std::vector<std::uint32_t> moving = {0, 1};
        const std::vector<std::uint32_t> refined =
            refineRegions(graph, feature, std::vector<double>(strip.vertexCount(), 1.0), moving, 10);
        // At the fixed point each seed is its region's vertex nearest the region's mean
        // feature (ties: the smaller index), and every vertex has a region.
        for (std::uint32_t k = 0; k < 2; ++k) {
            QCOMPARE(refined[moving[k]], k);
            double sum = 0.0, count = 0.0;
            for (std::size_t v = 0; v < refined.size(); ++v)
                if (refined[v] == k) {
                    sum += values[v];
                    count += 1.0;
                }
            const double mean = sum / count;
            for (std::size_t v = 0; v < refined.size(); ++v)
                if (refined[v] == k)
                    QVERIFY(std::abs(values[v] - mean) > std::abs(values[moving[k]] - mean) ||
                            (std::abs(values[v] - mean) == std::abs(values[moving[k]] - mean) && v >= moving[k]));
        }
        QCOMPARE(std::count(refined.begin(), refined.end(), kNoRegion), std::ptrdiff_t(0));
    }

    void partitionsAreConnectedAndNamed()
    {
        const TriangleMesh strip = stripMesh(kColumns);
        const VertexGraph graph = buildVertexGraph(strip.vertexCount(), strip.triangles);
        PoseFeature feature;
        feature.pose = 1;
        feature.values = columnFeature();
        for (const PartitionMethod method : {PartitionMethod::RegionGrowing, PartitionMethod::Hierarchical}) {
            QCOMPARE(parsePartitionMethod(partitionMethodName(method)), std::optional(method));
            const VertexLabeling labels =
                partitionPose(graph, feature, std::vector<double>(strip.vertexCount(), 1.0), {method, 2, 5});
            QCOMPARE(labels.count, std::uint32_t(2));
            QCOMPARE(labels.labels.size(), strip.vertexCount());
            // Two clusters of a line: a left and a right part, each column whole.
            for (unsigned c = 0; c < kColumns; ++c) {
                QCOMPARE(labels.labels[c], labels.labels[kColumns + c]);
                QVERIFY(c == 0 || labels.labels[c] == labels.labels[c - 1] || labels.labels[c] != labels.labels[0]);
            }
            QVERIFY(labels.labels.front() != labels.labels[kColumns - 1]);
        }
        QCOMPARE(partitionMethodName(PartitionMethod::Hierarchical), std::string_view("hierarchical"));
        QVERIFY(!parsePartitionMethod("kmeans"));
    }

    // Poses must share the first pose's triangles; a quad split along its other diagonal
    // covers the same region and passes.
    void posesKeepTheFirstPosesTopology()
    {
        const TriangleMesh strip = stripMesh(3);
        requireSameTopology(strip.triangles, strip.vertexCount(), strip, "p.obj");
        TriangleMesh fewer = strip;
        fewer.positions.pop_back();
        QVERIFY(meshLoadError([&] {
                    requireSameTopology(strip.triangles, strip.vertexCount(), fewer, "p.obj");
                }).starts_with("p.obj"));
        TriangleMesh flipped = strip; // quad 0 (0, 1, 4, 3) split along 1–3 instead of 0–4
        flipped.triangles[0] = {0, 1, 3};
        flipped.triangles[1] = {1, 4, 3};
        requireSameTopology(strip.triangles, strip.vertexCount(), flipped, "p.obj");
        TriangleMesh other = strip;
        other.triangles[0] = {0, 1, 5};
        QVERIFY(meshLoadError([&] {
                    requireSameTopology(strip.triangles, strip.vertexCount(), other, "p.obj");
                }).find("face 0") != std::string::npos);
    }

    // A translation channel read from a model made with the glTF builder: LINEAR between
    // keyframes; a missing animation or node is an error that names it.
    void clipsApplyTheirChannels()
    {
        tinygltf::Model model;
        model.buffers.emplace_back();
        model.nodes.emplace_back();
        tinygltf::AnimationSampler sampler;
        sampler.input = io::addGltfFloatAccessor(model, {0.0f, 2.0f}, TINYGLTF_TYPE_SCALAR, true);
        sampler.output = io::addGltfFloatAccessor(model, {0, 0, 0, 4, 0, -2}, TINYGLTF_TYPE_VEC3, false);
        sampler.interpolation = "LINEAR";
        tinygltf::AnimationChannel channel;
        channel.sampler = 0;
        channel.target_node = 0;
        channel.target_path = "translation";
        tinygltf::Animation animation;
        animation.samplers.push_back(sampler);
        animation.channels.push_back(channel);
        model.animations.push_back(animation);

        const GltfAnimationClip clip = readAnimationClip(model, 0, "a.gltf");
        QCOMPARE(clip.channels.size(), std::size_t(1));
        QCOMPARE(clip.keyframeTimes, (std::vector<double>{0.0, 2.0}));
        std::vector<NodeTransform> nodes(1);
        clip.apply(0.5, nodes);
        QVERIFY(glm::length(nodes[0].translation - glm::dvec3(1.0, 0.0, -0.5)) < 1e-12);
        QVERIFY(meshLoadError([&] {
                    (void)readAnimationClip(model, 1, "a.gltf");
                }).find("animation 1 does not exist (the file has 1)") != std::string::npos);
        model.animations[0].channels[0].target_node = 3;
        QVERIFY(!meshLoadError([&] { (void)readAnimationClip(model, 0, "a.gltf"); }).empty());
    }

    void skinKeepsTheWeldedVertices()
    {
        AnimationSkin skin;
        skin.jointCount = 2;
        skin.influences = 2;
        skin.bindPositions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
        skin.joints = {0, 1, 1, 0, 0, 0};
        skin.weights = {0.5, 0.5, 0.75, 0.25, 1.0, 0.0};
        skin.jointMatrices = {{glm::dmat4(1.0), glm::dmat4(2.0)}};
        const AnimationSkin kept = keepSkinVertices(skin, {2, 0});
        QCOMPARE(kept.bindPositions, (std::vector<glm::dvec3>{{2, 0, 0}, {0, 0, 0}}));
        QCOMPARE(kept.joints, (std::vector<std::uint32_t>{0, 0, 0, 1}));
        QCOMPARE(kept.weights, (std::vector<double>{1.0, 0.0, 0.5, 0.5}));
        QCOMPARE(kept.jointMatrices, skin.jointMatrices);
        QCOMPARE(kept.jointCount, std::size_t(2));
    }

    // One colour per label; the next labeling of the same mesh inherits colours where its
    // segments overlap the shown ones; reset forgets them.
    void segmentColorsFollowTheLabels()
    {
        const TriangleMesh strip = stripMesh(kColumns);
        const VertexGraph graph = buildVertexGraph(strip.vertexCount(), strip.triangles);
        const std::vector<double> areas(strip.vertexCount(), 1.0);
        SegmentColors colors;
        QVERIFY(colors.empty());
        const VertexLabeling halves = columnLabels({0, 0, 0, 0, 0, 1, 1, 1, 1, 1});
        colors.show(graph, areas, halves);
        QCOMPARE(colors.colors().size(), std::size_t(2));
        QVERIFY(!(colors.colors()[0] == colors.colors()[1]));
        const std::vector<WheelColor> first = colors.colors();
        const std::vector<std::uint32_t> rgba = vertexRgba8(colors.labeling(), colors.colors());
        QCOMPARE(rgba[0], packRgba8(first[0].rgb()));
        QCOMPARE(rgba[kColumns - 1], packRgba8(first[1].rgb()));

        colors.show(graph, areas, columnLabels({1, 1, 1, 1, 1, 0, 0, 0, 0, 0})); // the same parts, renamed
        QCOMPARE(colors.colors()[1], first[0]);
        QCOMPARE(colors.colors()[0], first[1]);
        colors.reset();
        QVERIFY(colors.empty());
        colors.showColored(halves, {first[1], first[0]});
        QCOMPARE(colors.colors()[0], first[1]);
    }

    void segmentationRecordsAreWrittenInTheirFormat()
    {
        QCOMPARE(segmentationFileFormat("a.JSON"), std::optional(SegmentationFileFormat::Json));
        QCOMPARE(segmentationFileFormat("a.csv"), std::optional(SegmentationFileFormat::Csv));
        QCOMPARE(segmentationFileFormat("a.gltf"), std::optional(SegmentationFileFormat::Gltf));
        QVERIFY(!segmentationFileFormat("a.glb"));
        QVERIFY(!segmentationFileFormat("json"));

        const MeshAnimation animation = bendingStrip();
        SegmenterSettings settings;
        settings.partition.clusters = 3;
        AnimationSegmenter segmenter(animation, settings);
        segmenter.run();
        const VertexLabeling segmentation = segmenter.segment(0.1);
        const SegmentationRecord record = makeSegmentationRecord(segmenter, "strip", 0.1, segmentation, {}, false);
        QCOMPARE(record.source, std::string("strip"));
        QCOMPARE(record.vertexCount, animation.vertexCount());
        QCOMPARE(record.poseCount, std::size_t(6));
        QCOMPARE(record.segmentation, segmentation);
        QCOMPARE(record.colors.size(), std::size_t(segmentation.count));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 (void)makeSegmentationRecord(segmenter, "strip", 0.1, segmentation,
                                                              std::vector<WheelColor>(segmentation.count + 1), false));

        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::filesystem::path json = std::filesystem::path(dir.path().toStdString()) / "s.json";
        writeSegmentationFile(json, SegmentationFileFormat::Json, record, animation);
        std::ifstream in(json);
        const nlohmann::json document = nlohmann::json::parse(in);
        QVERIFY(document.is_object());
        const std::filesystem::path csv = std::filesystem::path(dir.path().toStdString()) / "s.csv";
        writeSegmentationFile(csv, SegmentationFileFormat::Csv, record, animation);
        std::ifstream lines(csv);
        std::string header;
        std::getline(lines, header);
        QCOMPARE(header, std::string("vertex,label"));
        QVERIFY_THROWS_EXCEPTION(std::runtime_error,
                                 writeSegmentationFile(std::filesystem::path(dir.path().toStdString()) / "no" / "s.csv",
                                                       SegmentationFileFormat::Csv, record, animation));
    }
};

QTEST_GUILESS_MAIN(TestAnimationParts)
#include "tst_animation_parts.moc"
