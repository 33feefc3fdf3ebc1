// Exports of a segmentation: the CSV layout, the JSON document of
// docs/segmentation-format.md (parsed with QJsonDocument), and the glTF file read back
// without tinygltf (QJsonDocument + base64), so that "other tools can read it" is checked
// by a second reader.
#include "core/animation/segment_coloring.h"
#include "core/animation/segmentation_export.h"
#include "core/animation/segmentation_gltf.h"

#include "animation_fixtures.h"
#include "test_paths.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include <cstring>

using namespace trimlab;

namespace {

SegmentationRecord stripRecord(bool variable)
{
    SegmentationRecord r;
    r.source = "strip \"test\"";
    r.vertexCount = 8;
    r.faceCount = 6;
    r.poseCount = 3;
    r.feature.kind = FeatureKind::Velocity;
    r.partition.clusters = 2;
    r.partition.method = PartitionMethod::Hierarchical;
    r.h = 0.25;
    r.variableMode = variable;
    r.partitionedPoses = {1, 2};
    r.clustersPerPose = {2, 2};
    r.overSegmentCount = 3;
    r.segmentation = test::columnLabels({0, 0, 1, 1});
    r.colors = {paletteColor(0), paletteColor(1)};
    r.segmentAreas = {1.5, 1.5};
    if (variable) {
        r.variable = {test::columnLabels({0, 1, 1, 1}), test::columnLabels({0, 0, 0, 1})};
        r.variableColors = {{paletteColor(0), paletteColor(1)}, {paletteColor(0), paletteColor(2)}};
    }
    r.times = {10.0, 20.0, 30.0, 4.0, 0.5};
    return r;
}

} // namespace

class TestAnimationExport : public QObject {
    Q_OBJECT
private slots:
    void csv();
    void json();
    void jsonVariable();
    void gltfReadsBack();
    void unwritableFile();
};

void TestAnimationExport::csv()
{
    QCOMPARE(segmentationCsv(stripRecord(false)),
             std::string("vertex,label\n0,0\n1,0\n2,1\n3,1\n4,0\n5,0\n6,1\n7,1\n"));
    const std::string variable = segmentationCsv(stripRecord(true));
    QVERIFY(variable.starts_with("vertex,label,pose_1,pose_2\n0,0,0,0\n1,0,1,0\n"));
}

void TestAnimationExport::json()
{
    QJsonParseError error;
    const QJsonDocument doc =
        QJsonDocument::fromJson(QByteArray::fromStdString(segmentationJson(stripRecord(false))), &error);
    QVERIFY2(error.error == QJsonParseError::NoError, qPrintable(error.errorString()));
    const QJsonObject o = doc.object();
    QCOMPARE(o["format"].toString(), QString("trimlab-segmentation"));
    QCOMPARE(o["version"].toInt(), 1);
    QCOMPARE(o["source"].toString(), QString("strip \"test\""));
    QCOMPARE(o["segment_count"].toInt(), 2);
    QCOMPARE(o["h"].toDouble(), 0.25);
    QCOMPARE(o["clusters"].toInt(), 2);
    QCOMPARE(o["feature"].toString(), QString("velocity"));
    QCOMPARE(o["method"].toString(), QString("hierarchical"));
    QCOMPARE(o["mode"].toString(), QString("global"));
    QCOMPARE(o["over_segment_count"].toInt(), 3);
    QCOMPARE(o["labels"].toArray().size(), 8);
    QCOMPARE(o["labels"].toArray()[2].toInt(), 1);
    const QJsonArray segments = o["segments"].toArray();
    QCOMPARE(segments.size(), 2);
    QCOMPARE(segments[1].toObject()["color"].toArray(), (QJsonArray{0, 255, 0}));
    QCOMPARE(segments[1].toObject()["hex"].toString(), QString("#00ff00"));
    QCOMPARE(segments[1].toObject()["vertex_count"].toInt(), 4);
    const QJsonObject times = o["times_ms"].toObject();
    for (const char* stage : {"load", "features", "partitions", "over_segmentation", "cleaning"})
        QVERIFY2(times.contains(stage), stage);
    QCOMPARE(times["cleaning"].toDouble(), 0.5);
    QVERIFY(!o.contains("variable"));
}

void TestAnimationExport::jsonVariable()
{
    const QJsonObject o =
        QJsonDocument::fromJson(QByteArray::fromStdString(segmentationJson(stripRecord(true)))).object();
    QCOMPARE(o["mode"].toString(), QString("variable"));
    const QJsonArray variable = o["variable"].toArray();
    QCOMPARE(variable.size(), 2);
    QCOMPARE(variable[1].toObject()["pose"].toInt(), 2);
    QCOMPARE(variable[1].toObject()["colors"].toArray()[1].toArray(), (QJsonArray{0, 0, 255}));
    QCOMPARE(variable[0].toObject()["labels"].toArray().size(), 8);
}

// The _SEGMENT and COLOR_0 attributes decoded by hand from the embedded buffer.
void TestAnimationExport::gltfReadsBack()
{
    const TriangleMesh strip = test::stripMesh(4);
    const VertexLabeling labels = test::columnLabels({0, 0, 1, 1});
    const std::vector<WheelColor> colors = {paletteColor(2), paletteColor(3)};
    const QJsonObject o =
        QJsonDocument::fromJson(QByteArray::fromStdString(segmentationGltf(strip, labels, colors))).object();
    QCOMPARE(o["asset"].toObject()["version"].toString(), QString("2.0"));
    QCOMPARE(o["asset"].toObject()["extras"].toObject()["segment_count"].toInt(), 2);
    const QString uri = o["buffers"].toArray()[0].toObject()["uri"].toString();
    QVERIFY(uri.startsWith("data:application/octet-stream;base64,"));
    const QByteArray buffer = QByteArray::fromBase64(uri.section(',', 1).toLatin1());
    const QJsonObject attributes =
        o["meshes"].toArray()[0].toObject()["primitives"].toArray()[0].toObject()["attributes"].toObject();
    auto floats = [&](const QString& attribute) {
        const QJsonObject accessor = o["accessors"].toArray()[attributes[attribute].toInt()].toObject();
        const QJsonObject view = o["bufferViews"].toArray()[accessor["bufferView"].toInt()].toObject();
        std::vector<float> values(std::size_t(view["byteLength"].toInt()) / 4);
        std::memcpy(values.data(), buffer.constData() + view["byteOffset"].toInt(), values.size() * 4);
        return std::make_pair(accessor, values);
    };
    const auto [segmentAccessor, segment] = floats("_SEGMENT");
    QCOMPARE(segmentAccessor["type"].toString(), QString("SCALAR"));
    QCOMPARE(segmentAccessor["componentType"].toInt(), 5126);
    QCOMPARE(segment, (std::vector<float>{0, 0, 1, 1, 0, 0, 1, 1}));
    const auto [colorAccessor, color] = floats("COLOR_0");
    QCOMPARE(colorAccessor["type"].toString(), QString("VEC3"));
    QCOMPARE(std::vector<float>(color.begin() + 6, color.begin() + 9),
             (std::vector<float>{1, 1, 0})); // vertex 2: yellow
    const auto [positionAccessor, position] = floats("POSITION");
    QCOMPARE(positionAccessor["max"].toArray(), (QJsonArray{3, 1, 0}));
    QCOMPARE(position[3 * 5], 1.0f); // vertex 5 = (1, 1, 0)
    // The written file is also a mesh TrimLab loads.
    const std::filesystem::path path = test::outputDir() / "segmentation.gltf";
    writeSegmentationGltf(path, strip, labels, colors);
    QVERIFY(std::filesystem::file_size(path) > 100);
}

void TestAnimationExport::unwritableFile()
{
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, writeTextFile("/nonexistent-folder/x.json", "{}"));
}

QTEST_GUILESS_MAIN(TestAnimationExport)
#include "tst_animation_export.moc"
