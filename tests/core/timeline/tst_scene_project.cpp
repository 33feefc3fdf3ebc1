// Scene projects (project format version 3): several objects with meshes, placements,
// rules and the CSG expression round-trip exactly; damaged scenes name the element; the
// design histories of versions 1 and 2 are untouched, and a design whose static rule is
// one of the newer rules is written as version 3.
#include "project_load_error.h"
#include "test_paths.h"
#include "tst_timeline_fixtures.h"

#include "core/scene/object_transform.h"
#include "core/scene/shape_generators.h"
#include "core/timeline/project_file.h"
#include "core/trim/csg_expression.h"

#include <glm/gtc/matrix_transform.hpp>

#include <QtTest>

#include <filesystem>

using namespace trimlab;
using namespace trimlab::timeline;

namespace {

ProjectScene threeObjects()
{
    ProjectScene scene;
    ObjectTransform moved;
    moved.translation = {0.1, -1.0 / 3.0, 2.5};
    moved.rotationDegrees = {10.0, -20.0, 30.0};
    moved.scale = 0.7;
    // The third object keeps a matrix no ObjectTransform gives (a non-uniform scale, as
    // a glTF node may have); it must survive as its 16 doubles.
    const glm::dmat4 stretched = glm::scale(glm::dmat4(1.0), glm::dvec3(1.0, 2.0, 0.5));
    scene.objects.push_back({"sphere", makeIcosphere(glm::dvec3(0.0), 1.0, 2), glm::dmat4(1.0)});
    scene.objects.push_back({"ball", makeIcosphere(glm::dvec3(0.2), 0.6, 1), moved.modelMatrix()});
    scene.objects.push_back({"grid \"quoted\" ünïcode", test::gridMesh(5), stretched});
    scene.csg.expression = parseCsgExpression("(0 | 1) - 2", nullptr).value();
    scene.csg.objectRules[1] = StaticRule::Nonzero;
    scene.csg.objectRules[2] = StaticRule::absAtLeast(3);
    return scene;
}

ProjectFileError loadError(const std::string& text)
{
    return test::projectLoadError(text, "scene.trimlab");
}

// `text` with the first occurrence of `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to)
{
    const std::size_t at = text.find(from);
    if (at == std::string::npos)
        qFatal("the saved scene lacks '%s'", from.c_str());
    return text.replace(at, from.size(), to);
}

} // namespace

class TestSceneProject : public QObject {
    Q_OBJECT
private slots:
    void roundTripIsExact();
    void savedFileReopens();
    void historyLoaderRefusesAScene();
    void newerRulesWriteVersion3();
    void unstorableScenesAreRefused();
    void errorsNameTheElement_data();
    void errorsNameTheElement();
};

void TestSceneProject::roundTripIsExact()
{
    const ProjectScene scene = threeObjects();
    ProjectExtras extras;
    extras.staticRule = StaticRule::atLeast(2);
    extras.view = ProjectView{{1.0, 2.0, 3.0}, {0.1, 0.2, 0.3}, {0.0, 1.0, 0.0}, 40.0};
    const std::string text = sceneProjectJson(scene, extras);
    QVERIFY(text.find("\"version\": 3") != std::string::npos);
    const Project project = parseProject(text, "scene.trimlab");
    QVERIFY(project.scene.has_value());
    QVERIFY(*project.scene == scene);
    QCOMPARE(project.scene->objects[2].modelMatrix, scene.objects[2].modelMatrix);
    QCOMPARE(project.scene->csg.objectRules[2], std::optional<StaticRule>(StaticRule::absAtLeast(3)));
    QVERIFY(!project.scene->csg.objectRules[0].has_value());
    QCOMPARE(formatCsgExpression(project.scene->csg.expression), std::string("0 | 1 - 2"));
    QVERIFY(project.extras == extras);
    QVERIFY(project.timeline.base().positions.empty());
    // Saving what was read writes the same bytes.
    QCOMPARE(sceneProjectJson(*project.scene, project.extras), text);
}

void TestSceneProject::savedFileReopens()
{
    const std::filesystem::path dir = test::outputDir() / "scene-project";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::filesystem::path path = dir / "assembly.trimlab";
    saveSceneProject(threeObjects(), path);
    const Project project = readProject(path);
    QVERIFY(project.scene && *project.scene == threeObjects());
}

void TestSceneProject::historyLoaderRefusesAScene()
{
    const std::filesystem::path dir = test::outputDir() / "scene-project-history";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::filesystem::path path = dir / "assembly.trimlab";
    saveSceneProject(threeObjects(), path);
    try {
        (void)loadProject(path);
        QFAIL("loadProject read a scene as a history");
    } catch (const ProjectFileError& error) {
        QCOMPARE(error.where(), std::string("scene"));
        QVERIFY2(error.reason().find("a scene of 3 object(s), not a deformation history") != std::string::npos,
                 error.what());
    }
}

// A history keeps the lowest version that holds it: 1 for a plain mesh with one of the
// thesis's rules, 3 once its static rule is one that older TrimLabs would not know.
void TestSceneProject::newerRulesWriteVersion3()
{
    const Timeline history(test::gridMesh(3));
    ProjectExtras extras;
    extras.staticRule = StaticRule::AlternatingBorder;
    QVERIFY(projectJson(history, extras).find("\"version\": 1") != std::string::npos);
    extras.staticRule = StaticRule::Negative;
    const std::string text = projectJson(history, extras);
    QVERIFY(text.find("\"version\": 3") != std::string::npos);
    const Project project = parseProject(text, "negative.trimlab");
    QVERIFY(!project.scene.has_value());
    QCOMPARE(project.extras.staticRule, std::optional<StaticRule>(StaticRule::Negative));
}

void TestSceneProject::unstorableScenesAreRefused()
{
    ProjectScene empty;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)sceneProjectJson(empty));
    ProjectScene mirrored = threeObjects();
    mirrored.objects[1].modelMatrix = glm::scale(glm::dmat4(1.0), glm::dvec3(-1.0, 1.0, 1.0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)sceneProjectJson(mirrored));
    ProjectScene missingOperand = threeObjects();
    missingOperand.objects.pop_back();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)sceneProjectJson(missingOperand));
}

void TestSceneProject::errorsNameTheElement_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("where");
    QTest::addColumn<QString>("reason");
    const std::string good = sceneProjectJson(threeObjects());
    const auto row = [](const char* name, const std::string& text, const char* where, const char* reason) {
        QTest::newRow(name) << QString::fromStdString(text) << where << reason;
    };
    row("no objects", replaced(good, "\"objects\": [", "\"objects\": [], \"x\": ["), "scene.objects",
        "must hold 1 to 32 objects, not 0");
    row("csg names a missing object", replaced(good, "\"csg\": \"0 | 1 - 2\"", "\"csg\": \"0 - 5\""), "scene.csg",
        "names object 5, but the scene has 3");
    row("bad csg", replaced(good, "\"csg\": \"0 | 1 - 2\"", "\"csg\": \"0 -\""), "scene.csg", "");
    row("unknown object rule", replaced(good, "\"rule\": \"nonzero\"", "\"rule\": \"odd\""), "scene.objects[1].rule",
        "unknown static rule 'odd'");
    row("mirroring matrix", replaced(good, "\"model_matrix\": [\n     1.0,", "\"model_matrix\": [\n     -1.0,"),
        "scene.objects[0].model_matrix", "does not preserve orientation");
    row("short matrix", replaced(good, "\"model_matrix\": [\n     1.0,", "\"model_matrix\": [\n"),
        "scene.objects[0].model_matrix", "must hold 16 numbers (column-major), not 15");
    row("missing name", replaced(good, "\"name\": \"sphere\"", "\"nom\": \"sphere\""), "scene.objects[0]",
        "missing field 'name'");
}

void TestSceneProject::errorsNameTheElement()
{
    QFETCH(QString, text);
    QFETCH(QString, where);
    QFETCH(QString, reason);
    const ProjectFileError error = loadError(text.toStdString());
    QVERIFY2(QString::fromStdString(error.where()) == where, error.what());
    QVERIFY2(QString::fromStdString(error.reason()).startsWith(reason), error.what());
}

QTEST_GUILESS_MAIN(TestSceneProject)
#include "tst_scene_project.moc"
