// The JSON pieces of the project file, each on its own: base64, meshes, scenes, strokes,
// surface definitions and control moves written and read back exactly, the errors that
// name the bad element, the stroke checks, and the project error's three parts.
#include "core/timeline/base64.h"
#include "core/timeline/mesh_json.h"
#include "core/timeline/project_file_error.h"
#include "core/timeline/project_scene.h"
#include "core/timeline/scene_json.h"
#include "core/timeline/stroke_json.h"
#include "core/timeline/stroke_validation.h"
#include "core/timeline/surface_json.h"

#include "core/io/json_fields.h"
#include "core/surface/nurbs_primitives.h"
#include "core/surface/subdivision_cages.h"

#include <QtTest>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

using namespace trimlab;
using namespace trimlab::timeline;
using nlohmann::json;

namespace {

// The JsonPathError `read` throws, as "PATH: REASON"; "" when none.
std::string pathError(const std::function<void()>& read)
{
    try {
        read();
    } catch (const io::JsonPathError& e) {
        return e.path() + ": " + e.reason();
    }
    return "";
}

// Through text, as a project file stores it.
json reparsed(const json& value)
{
    return json::parse(value.dump());
}

TriangleMesh tetrahedron()
{
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1.0f / 3.0f}};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return mesh;
}

deform::Stroke sampleStroke()
{
    deform::Stroke stroke;
    stroke.anchor = {0.1, 0.2, 1.0 / 3.0};
    stroke.anchorTriangle = 7;
    stroke.drag = {0.0, -0.25, 0.5};
    stroke.brush.radius = 0.4;
    stroke.brush.profile = deform::FalloffProfile::Sharp;
    stroke.brush.smoothingIterations = 3;
    return stroke;
}

} // namespace

class TestTimelineJson : public QObject {
    Q_OBJECT

private slots:
    void base64RoundTripsAndRefusesNonCanonicalText()
    {
        const std::vector<std::uint8_t> bytes = {0, 1, 2, 250, 251, 252, 253};
        const std::string text = base64Encode(bytes);
        QCOMPARE(text.size(), std::size_t(12));
        QCOMPARE(base64Decode(text), bytes);
        QCOMPARE(base64Encode(std::vector<std::uint8_t>{'M', 'a', 'n'}), std::string("TWFu"));
        QCOMPARE(base64Encode(std::vector<std::uint8_t>{'M'}), std::string("TQ=="));
        QVERIFY(base64Decode("").empty());
        for (const char* bad : {"TWF", "TW#u", "TQ==TWFu", "TR==", "TW Fu"})
            QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)base64Decode(bad));
        try {
            (void)base64Decode("TWFuTW#u");
        } catch (const std::invalid_argument& e) {
            QVERIFY2(std::string(e.what()).find("offset 6") != std::string::npos, e.what());
        }
    }

    void meshesRoundTripBitForBit()
    {
        const TriangleMesh mesh = tetrahedron();
        QCOMPARE(readMesh(reparsed(meshJson(mesh)), "mesh"), mesh);
        json broken = meshJson(mesh);
        broken.erase("triangles");
        QCOMPARE(pathError([&] { (void)readMesh(broken, "base"); }), std::string("base: missing field 'triangles'"));
        QVERIFY(!pathError([] { (void)readMesh(json::array(), "base"); }).empty());
    }

    void scenesRoundTripAndRefuseWhatCannotBeStored()
    {
        ProjectScene scene;
        scene.objects.push_back(SceneObject{"a", tetrahedron(), glm::dmat4(1.0)});
        glm::dmat4 moved(1.0);
        moved[3] = glm::dvec4(0.1, 2.0, -3.0, 1.0);
        scene.objects.push_back(SceneObject{"b", tetrahedron(), moved});
        scene.csg.expression =
            CsgExpression::combine(CsgOperation::Union, {CsgExpression::operand(0), CsgExpression::operand(1)});
        scene.csg.objectRules[1] = StaticRule::Nonzero;
        const ProjectScene back = readScene(reparsed(sceneJson(scene)), "scene");
        QVERIFY(back == scene);
        QCOMPARE(back.objects[1].modelMatrix, moved);
        ProjectScene shifted = back;
        shifted.objects[0].modelMatrix[3][0] += 1.0;
        QVERIFY(!(shifted == scene));

        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)sceneJson(ProjectScene{}));
        ProjectScene mirrored = scene;
        mirrored.objects[0].modelMatrix[0][0] = -1.0;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)sceneJson(mirrored));
        ProjectScene missing = scene;
        missing.csg.expression =
            CsgExpression::combine(CsgOperation::Union, {CsgExpression::operand(0), CsgExpression::operand(5)});
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)sceneJson(missing));
        QVERIFY(!pathError([] { (void)readScene(json::object(), "scene"); }).empty());
    }

    void strokesRoundTripAndNameTheirBadFields()
    {
        const deform::Stroke stroke = sampleStroke();
        QCOMPARE(readStrokeJson(reparsed(strokeJson(stroke)), "s", true), stroke);
        deform::Stroke loose = stroke;
        loose.anchorTriangle.reset();
        QVERIFY(!strokeJson(loose).contains("triangle"));
        QCOMPARE(readStrokeJson(strokeJson(loose), "s", true), loose);

        json text = strokeJson(stroke);
        text["profile"] = "soft";
        QCOMPARE(pathError([&] { (void)readStrokeJson(text, "s", true); }),
                 std::string("s.profile: unknown profile 'soft' (known: smooth, linear, sharp)"));
        text = strokeJson(stroke);
        text["colour"] = "red";
        QVERIFY(pathError([&] { (void)readStrokeJson(text, "s", true); }).starts_with("s.colour: "));
        QCOMPARE(readStrokeJson(text, "s", false), stroke); // unknown fields tolerated
        text = strokeJson(stroke);
        text.erase("drag");
        QVERIFY(pathError([&] { (void)readStrokeJson(text, "s", true); }).find("drag") != std::string::npos);

        deform::Stroke bad = stroke;
        bad.brush.radius = 0.0;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)strokeJson(bad));
    }

    void strokeProblemsNameTheFirstFault()
    {
        deform::Stroke stroke = sampleStroke();
        QCOMPARE(strokeProblem(stroke), std::string());
        stroke.brush.radius = -1.0;
        QCOMPARE(strokeProblem(stroke), std::string("the radius must be finite and > 0"));
        stroke.anchor.x = std::nan(""); // the anchor is checked before the radius
        QCOMPARE(strokeProblem(stroke), std::string("the anchor is not finite"));
        stroke = sampleStroke();
        stroke.drag.y = std::numeric_limits<double>::infinity();
        QCOMPARE(strokeProblem(stroke), std::string("the drag is not finite"));
        stroke = sampleStroke();
        stroke.brush.smoothingStep = 1.5;
        QCOMPARE(strokeProblem(stroke), std::string("the smoothing step must be in (0, 1]"));
        stroke = sampleStroke();
        stroke.brush.smoothingIterations = int(kMaxSmoothingIterations) + 1;
        QCOMPARE(strokeProblem(stroke), std::string("the smoothing iterations must be in [0, 10000]"));
        stroke.brush.smoothingIterations = int(kMaxSmoothingIterations);
        QCOMPARE(strokeProblem(stroke), std::string());
    }

    void surfaceDefinitionsAndControlMovesRoundTrip()
    {
        const SurfaceDefinition nurbs = nurbsDefinition(makeNurbsTorus({0.0, 0.5, 0.0}, 1.0, 0.3), 40, 20);
        QVERIFY(readSurfaceDefinition(reparsed(surfaceDefinitionJson(nurbs)), "surface") == nurbs);
        const SurfaceDefinition cage =
            subdivisionDefinition(cubeCage(0.75), SubdivisionSettings{2, SubdivisionMode::Uniform});
        QVERIFY(readSurfaceDefinition(reparsed(surfaceDefinitionJson(cage)), "surface") == cage);
        json badLevel = surfaceDefinitionJson(cage);
        badLevel["level"] = 99;
        QVERIFY(pathError([&] { (void)readSurfaceDefinition(badLevel, "surface"); }).starts_with("surface.level"));

        const std::vector<ControlPointMove> moves = {{3, {0.1, 0.2, 0.3}, {1.0 / 3.0, 0.0, -2.0}},
                                                     {9, {0, 0, 0}, {0, 1e-300, 0}}};
        QCOMPARE(readControlMoves(reparsed(controlMovesJson(moves)), "moves"), moves);
        json uneven = controlMovesJson(moves);
        uneven["indices"] = controlMovesJson({moves[0]})["indices"];
        QVERIFY(!pathError([&] { (void)readControlMoves(uneven, "moves"); }).empty());
        QVERIFY(!pathError([&] { (void)readControlMoves(controlMovesJson({}), "moves"); }).empty());
    }

    void projectErrorsReadFileWhereReason()
    {
        const ProjectFileError error("old.trimlab", "", "version 7 is newer than this TrimLab (1)");
        QCOMPARE(std::string(error.what()), std::string("old.trimlab: version 7 is newer than this TrimLab (1)"));
        const io::DocumentFileError& base = error;
        QCOMPARE(base.file(), std::string("old.trimlab"));
        QCOMPARE(base.where(), std::string());
        const ProjectFileError inside("s.trimlab", "frames[3].after", "CRC mismatch");
        QCOMPARE(std::string(inside.what()), std::string("s.trimlab: frames[3].after: CRC mismatch"));
    }
};

QTEST_APPLESS_MAIN(TestTimelineJson)
#include "tst_timeline_json.moc"
