// The pieces of core/io that the document readers and writers share: the document error's
// three parts, typed JSON fields with their paths, the nesting guard, the up-front check
// of output paths, lower-case extensions, and the glTF builder's views, accessors, scene
// and morph animation.
#include "core/io/document_file_error.h"
#include "core/io/file_extension.h"
#include "core/io/gltf_builder.h"
#include "core/io/json_fields.h"
#include "core/io/json_nesting.h"
#include "core/io/output_paths.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

using namespace trimlab;
using nlohmann::json;

namespace {

class SampleFileError : public io::DocumentFileError {
public:
    using DocumentFileError::DocumentFileError;
};

// What `body` throws as a JsonPathError, as "PATH: REASON"; "" when it throws nothing.
template <class Body>
std::string pathError(Body&& body)
{
    try {
        body();
    } catch (const io::JsonPathError& e) {
        return e.path() + ": " + e.reason();
    }
    return "";
}

std::vector<float> floatsOf(const tinygltf::Model& model, int viewIndex)
{
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(viewIndex)];
    std::vector<float> values(view.byteLength / sizeof(float));
    std::memcpy(values.data(), model.buffers[0].data.data() + view.byteOffset, view.byteLength);
    return values;
}

} // namespace

class TestIoParts : public QObject {
    Q_OBJECT

private slots:
    void extensionsCompareInLowerCase()
    {
        QCOMPARE(io::lowercaseExtension("out/Mesh.GLB"), std::string(".glb"));
        QCOMPARE(io::lowercaseExtension("a.b/Rig.GlTf"), std::string(".gltf"));
        QCOMPARE(io::lowercaseExtension("scan.obj.GZ"), std::string(".gz")); // the last one only
        QCOMPARE(io::lowercaseExtension("folder.d/README"), std::string());
        QCOMPARE(io::lowercaseExtension(".hidden"), std::string()); // a dot file has no extension
    }

    void documentErrorsReadFileWhereReason()
    {
        const SampleFileError inside("scene.trimlab", "frames[3].after", "CRC mismatch");
        QCOMPARE(std::string(inside.what()), std::string("scene.trimlab: frames[3].after: CRC mismatch"));
        QCOMPARE(inside.file(), std::string("scene.trimlab"));
        QCOMPARE(inside.where(), std::string("frames[3].after"));
        QCOMPARE(inside.reason(), std::string("CRC mismatch"));
        const SampleFileError whole("a.json", "", "the document is empty");
        QCOMPARE(std::string(whole.what()), std::string("a.json: the document is empty"));
    }

    void jsonFieldsNameThePathOfTheBadValue()
    {
        QCOMPARE(io::fieldPath("", "sets"), std::string("sets"));
        QCOMPARE(io::indexPath(io::fieldPath(io::indexPath("sets", 0), "strokes"), 2),
                 std::string("sets[0].strokes[2]"));
        QCOMPARE(io::jsonTypeText(json::array()), std::string("an array"));
        QCOMPARE(io::jsonTypeText(json(3)), std::string("an integer"));
        QCOMPARE(io::jsonTypeText(json(0.5)), std::string("a number"));

        const json object = json::parse(R"({"radius": 0.5, "count": 7, "name": "a", "at": [1, 2, 3], "none": null})");
        QCOMPARE(pathError([&] { io::requireArray(object, "s"); }), std::string("s: must be an array, not an object"));
        QCOMPARE(pathError([&] { io::requireObject(object["at"], "s.at"); }),
                 std::string("s.at: must be an object, not an array"));
        QCOMPARE(pathError([&] {
                     io::rejectUnknownFields(object, {"radius", "count", "name", "at"}, "s");
                 }),
                 std::string("s.none: unknown field (known fields: radius, count, name, at)"));
        QCOMPARE(pathError([&] { (void)io::requiredField(object, "size", "s"); }),
                 std::string("s: missing field 'size'"));
        QVERIFY(io::requiredField(object, "count", "s") == json(7));
        QVERIFY(io::optionalField(object, "none") == nullptr);
        QVERIFY(io::optionalField(object, "size") == nullptr);
        QVERIFY(*io::optionalField(object, "name") == json("a"));

        QCOMPARE(io::finiteNumber(object["count"], "c"), 7.0);
        QCOMPARE(pathError([&] { (void)io::finiteNumber(object["name"], "s.name"); }),
                 std::string("s.name: must be a number, not a string"));
        QCOMPARE(io::integerInRange(object["count"], 1, 7, "c"), std::int64_t(7));
        QCOMPARE(pathError([&] { (void)io::integerInRange(object["count"], 1, 6, "c"); }),
                 std::string("c: must be an integer in [1, 6], not 7"));
        QCOMPARE(pathError([&] { (void)io::integerInRange(object["radius"], 0, 9, "r"); }),
                 std::string("r: must be an integer in [0, 9], not a number"));
        QCOMPARE(pathError([&] { (void)io::integerInRange(json(-2), 0, 9, "n"); }),
                 std::string("n: must be an integer in [0, 9], not -2"));
        QCOMPARE(io::stringValue(object["name"], "n"), std::string("a"));
        QCOMPARE(pathError([&] { (void)io::stringValue(object["count"], "n"); }),
                 std::string("n: must be a string, not an integer"));
        QCOMPARE(io::dvec3Value(object["at"], "at"), glm::dvec3(1, 2, 3));
        QCOMPARE(pathError([&] { (void)io::dvec3Value(json::parse("[1, 2]"), "at"); }),
                 std::string("at: must be an array of 3 numbers [x, y, z]"));
        QCOMPARE(pathError([&] { (void)io::dvec3Value(json::parse(R"([1, "y", 3])"), "at"); }),
                 std::string("at[1]: must be a number, not a string"));
        const glm::dvec3 awkward(0.1, 1.0 / 3.0, -2.5e-300);
        QCOMPARE(io::dvec3Value(json::parse(io::dvec3Json(awkward).dump()), "p"), awkward);
    }

    void syntaxErrorsGiveLineColumnAndTruncation()
    {
        QCOMPARE(io::textPosition("ab\ncd", 4).line, std::size_t(2));
        QCOMPARE(io::textPosition("ab\ncd", 4).column, std::size_t(2));
        QCOMPARE(io::textPosition("ab", 99).column, std::size_t(3));
        QVERIFY(io::parseJsonText(R"({"a": [1, 2]})")["a"][1] == json(2));

        try {
            (void)io::parseJsonText("{\n  \"a\": [1, 2");
            QFAIL("no JsonSyntaxError");
        } catch (const io::JsonSyntaxError& e) {
            QVERIFY(e.truncated());
            QVERIFY2(io::jsonSyntaxErrorText(e).starts_with("truncated JSON at line 2"), e.what());
        }
        try {
            (void)io::parseJsonText("{\n  \"a\": [1, }");
            QFAIL("no JsonSyntaxError");
        } catch (const io::JsonSyntaxError& e) {
            QVERIFY(!e.truncated());
            QCOMPARE(e.position().line, std::size_t(2));
            QCOMPARE(e.position().column, std::size_t(12));
            QVERIFY2(io::jsonSyntaxErrorText(e).starts_with("invalid JSON at line 2, column 12: "), e.what());
        }
        try {
            (void)io::parseJsonText("[[[[1]]]]", 3);
            QFAIL("no JsonSyntaxError");
        } catch (const io::JsonSyntaxError& e) {
            QCOMPARE(e.position().column, std::size_t(4));
            QVERIFY2(e.reason().find("deeper than 3 levels") != std::string::npos, e.what());
        }
        QVERIFY_THROWS_EXCEPTION(io::JsonSyntaxError, (void)io::parseJsonText("  \n "));
    }

    // The whole-document parse turns both kinds of error into the format's own error.
    void documentReadersReportTheirOwnErrors()
    {
        const auto readCount = [](std::string_view text) {
            return io::readJsonDocument<SampleFileError>(text, "n.json", [](const json& document) {
                return io::integerInRange(io::requiredField(document, "n", ""), 0, 10, "n");
            });
        };
        QCOMPARE(readCount(R"({"n": 4})"), std::int64_t(4));
        try {
            (void)readCount(R"({"n": 40})");
            QFAIL("no error");
        } catch (const SampleFileError& e) {
            QCOMPARE(e.where(), std::string("n"));
            QCOMPARE(std::string(e.what()), std::string("n.json: n: must be an integer in [0, 10], not 40"));
        }
        try {
            (void)readCount(R"({"n": )");
            QFAIL("no error");
        } catch (const SampleFileError& e) {
            QCOMPARE(e.where(), std::string());
            QVERIFY2(e.reason().starts_with("truncated JSON at line 1"), e.what());
        }
    }

    void nestingGuardFindsTheFirstTooDeepBracket()
    {
        QCOMPARE(io::jsonTooDeepAt("[[1], {\"a\": [2]}]", 3), std::string_view::npos);
        QCOMPARE(io::jsonTooDeepAt("[[1], {\"a\": [2]}]", 2), std::size_t(12)); // the [ inside the object
        QCOMPARE(io::jsonTooDeepAt("[[1], {\"a\": [2]}]", 1), std::size_t(1));
        const std::string_view quoted = "[\"[[[[\", {\"\\\"[[\": 1}]";  // ["[[[[", {"\"[[": 1}]
        QCOMPARE(io::jsonTooDeepAt(quoted, 2), std::string_view::npos); // brackets in strings
        QCOMPARE(io::jsonTooDeepAt("]]][[", 1), std::size_t(4));        // stray closers do not go below 0
        QCOMPARE(io::jsonTooDeepAt("", 0), std::string_view::npos);
    }

    void outputPathsAreCheckedBeforeAnyWork()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::filesystem::path root = dir.path().toStdString();
        const std::string file = (root / "out.png").string();
        QCOMPARE(io::checkOutputPaths({{"-o", file}, {"--depth", ""}}), std::optional<std::string>());
        QCOMPARE(io::checkOutputPaths({}), std::optional<std::string>());
        QCOMPARE(io::checkOutputPaths({{"-o", root.string()}}),
                 std::optional<std::string>("-o " + root.string() + " is a folder; give a file name"));
        const std::string missing = (root / "nowhere" / "x.png").string();
        QCOMPARE(io::checkOutputPaths({{"-o", missing}}),
                 std::optional<std::string>("-o " + missing + ": the folder " + (root / "nowhere").string() +
                                            " does not exist"));
        std::ofstream(root / "plain") << "x";
        const std::string underFile = (root / "plain" / "x.png").string();
        QCOMPARE(io::checkOutputPaths({{"-o", underFile}}),
                 std::optional<std::string>("-o " + underFile + ": " + (root / "plain").string() + " is not a folder"));
        const std::string sameFile = (root / "." / "out.png").string();
        QCOMPARE(io::checkOutputPaths({{"-o", file}, {"--ids", sameFile}}),
                 std::optional<std::string>("-o and --ids both name " + sameFile + "; give each output its own file"));
        QVERIFY(io::checkOutputPaths({{"-o", std::string("a\0b", 3)}}).has_value());
    }

    // Views are 4-byte aligned in buffer 0, bounds are exact, the sparse accessor holds
    // only the non-zero values, the scene is the default, and the morph animation steps.
    void gltfBuilderLaysOutOneMeshScene()
    {
        tinygltf::Model model;
        model.buffers.emplace_back();
        const std::uint8_t odd[3] = {1, 2, 3};
        const int oddView = io::addGltfBufferView(model, odd, 3, 0);
        const std::vector<glm::vec3> positions = {{0, 1, 2}, {-1, 5, 0.25f}, {3, -2, 1}};
        tinygltf::Primitive primitive;
        primitive.attributes["POSITION"] =
            io::addGltfVec3Accessor(model, positions, TINYGLTF_TARGET_ARRAY_BUFFER, true);
        primitive.indices = io::addGltfTriangleIndices(model, {{0, 1, 2}});
        const int node = io::addGltfSingleMeshScene(model, primitive, "mesh");

        QCOMPARE(oddView, 0);
        QCOMPARE(model.bufferViews[1].byteOffset % 4, std::size_t(0));
        QCOMPARE(model.bufferViews[1].byteOffset, std::size_t(4));
        const tinygltf::Accessor& position = model.accessors[std::size_t(primitive.attributes["POSITION"])];
        QCOMPARE(position.count, std::size_t(3));
        QCOMPARE(position.minValues, (std::vector<double>{-1, -2, 0.25}));
        QCOMPARE(position.maxValues, (std::vector<double>{3, 5, 2}));
        QCOMPARE(floatsOf(model, position.bufferView), (std::vector<float>{0, 1, 2, -1, 5, 0.25f, 3, -2, 1}));
        const tinygltf::Accessor& indices = model.accessors[std::size_t(primitive.indices)];
        QCOMPARE(indices.count, std::size_t(3));
        QCOMPARE(indices.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
        QCOMPARE(model.bufferViews[std::size_t(indices.bufferView)].target, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        QCOMPARE(model.defaultScene, 0);
        QCOMPARE(model.scenes[0].nodes, std::vector<int>{node});
        QCOMPARE(model.nodes[std::size_t(node)].mesh, 0);
        QCOMPARE(model.nodes[std::size_t(node)].skin, -1);

        const int sparse = io::addGltfSparseVec3Accessor(model, {{0, 0, 0}, {0, 2, 0}, {0, 0, 0}, {1, 0, -3}});
        const tinygltf::Accessor& displacement = model.accessors[std::size_t(sparse)];
        QCOMPARE(displacement.bufferView, -1);
        QCOMPARE(displacement.count, std::size_t(4));
        QVERIFY(displacement.sparse.isSparse);
        QCOMPARE(displacement.sparse.count, 2);
        QCOMPARE(floatsOf(model, displacement.sparse.values.bufferView), (std::vector<float>{0, 2, 0, 1, 0, -3}));
        QCOMPARE(displacement.minValues, (std::vector<double>{0, 0, -3}));
        QCOMPARE(displacement.maxValues, (std::vector<double>{1, 2, 0}));

        io::addGltfMorphStepAnimation(model, "frames", {0.0f, 0.5f, 1.0f}, 1);
        const tinygltf::Animation& animation = model.animations.back();
        QCOMPARE(animation.samplers[0].interpolation, std::string("STEP"));
        QCOMPARE(animation.channels[0].target_path, std::string("weights"));
        const tinygltf::Accessor& times = model.accessors[std::size_t(animation.samplers[0].input)];
        QCOMPARE(times.minValues, std::vector<double>{0.0});
        QCOMPARE(times.maxValues, std::vector<double>{1.0});
        const tinygltf::Accessor& weights = model.accessors[std::size_t(animation.samplers[0].output)];
        // Keyframe 0 shows the base mesh; keyframes 1 and 2 show targets 0 and 1.
        QCOMPARE(floatsOf(model, weights.bufferView), (std::vector<float>{0, 0, 1, 0, 0, 1}));
    }
};

QTEST_GUILESS_MAIN(TestIoParts)
#include "tst_io_parts.moc"
