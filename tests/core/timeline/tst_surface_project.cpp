// Project files of editable-surface histories (format version 2): a NURBS and a
// subdivision history round-trip bit-exactly, malformed control moves and surface
// definitions give exact errors naming the JSON path, and version-1 files still load.
#include "test_paths.h"

#include "core/timeline/control_edit.h"
#include "core/catalog/fig8_13_history.h"
#include "core/surface/subdivision_cages.h"
#include "core/timeline/binary_array.h"
#include "core/timeline/project_file.h"

#include <nlohmann/json.hpp>

#include <QTemporaryDir>
#include <QtTest>

#include <cstring>

using namespace trimlab;
using namespace trimlab::timeline;
using nlohmann::json;

namespace {

template <typename T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b)
{
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// Every frame's arrays and control moves, the base mesh and the surface compared by bits.
void requireBitIdentical(const Timeline& a, const Timeline& b)
{
    QVERIFY(a == b);
    QVERIFY(sameBytes(a.base().positions, b.base().positions));
    QVERIFY(sameBytes(a.currentControlPoints(), b.currentControlPoints()));
    QVERIFY(sameBytes(a.surface()->controlPoints(), b.surface()->controlPoints()));
    for (int f = 1; f < a.frameCount(); ++f) {
        QVERIFY(sameBytes(a.frame(f).after, b.frame(f).after));
        const std::vector<ControlPointMove>& x = a.frame(f).controlMoves;
        const std::vector<ControlPointMove>& y = b.frame(f).controlMoves;
        QCOMPARE(x.size(), y.size());
        for (std::size_t k = 0; k < x.size(); ++k) { // field by field: the struct has padding
            QCOMPARE(x[k].index, y[k].index);
            QVERIFY(std::memcmp(&x[k].before, &y[k].before, sizeof(glm::dvec3)) == 0);
            QVERIFY(std::memcmp(&x[k].after, &y[k].after, sizeof(glm::dvec3)) == 0);
        }
    }
}

// A subdivision history with a crease, a corner and an edit whose target has -0.0.
Timeline subdivisionHistory()
{
    SubdivisionCage cage = cubeCage(1.0);
    cage.creases.push_back({0, 1, 2.5f});
    cage.corners.push_back({6, kInfiniteSharpness});
    const SurfaceDefinition definition = subdivisionDefinition(cage, SubdivisionSettings{2, SubdivisionMode::Uniform});
    Timeline history = surfaceTimeline(definition, DynamicRule::ConstructiveAdditive);
    EditableSurface surface(definition);
    const ControlPointTarget pull{2, glm::dvec3(-0.0, 1.0 / 3.0, 1.7)};
    appendControlEdit(history, surface, std::span(&pull, 1));
    return history;
}

std::string errorOf(const std::string& text)
{
    try {
        (void)parseProject(text, "p.trimlab");
    } catch (const ProjectFileError& error) {
        return error.what();
    }
    return "(no error)";
}

} // namespace

class TestSurfaceProject : public QObject {
    Q_OBJECT
private slots:
    void nurbsHistoryRoundTripsBitExactly();
    void subdivisionHistoryRoundTripsBitExactly();
    void plainHistoriesStayVersionOne();
    void versionOneFilesStillLoad();
    void versionTwoExampleLoads();
    void malformedControlMovesGiveExactErrors_data();
    void malformedControlMovesGiveExactErrors();
};

void TestSurfaceProject::nurbsHistoryRoundTripsBitExactly()
{
    const Timeline history = fig8_13NurbsHistory();
    QTemporaryDir dir;
    const std::filesystem::path path = (dir.path() + "/fig.trimlab").toStdString();
    saveProject(history, path);
    const Timeline loaded = loadProject(path);
    requireBitIdentical(history, loaded);
    QCOMPARE(json::parse(projectJson(loaded))["version"].get<int>(), 2);
    QCOMPARE(projectJson(loaded), projectJson(history)); // writing is deterministic
    // Editing can go on from the loaded history.
    EditableSurface surface(*loaded.surface());
    requireSurfaceMatchesTimeline(surface, loaded);
}

void TestSurfaceProject::subdivisionHistoryRoundTripsBitExactly()
{
    const Timeline history = subdivisionHistory();
    const Timeline loaded = parseProject(projectJson(history), "sub.trimlab").timeline;
    requireBitIdentical(history, loaded);
    QVERIFY(std::signbit(loaded.frame(1).controlMoves[0].after.x)); // -0.0 survived
    QCOMPARE(loaded.surface()->subdivision().cage.creases[0].sharpness, 2.5f);
    QCOMPARE(loaded.surface()->subdivision().settings.mode, SubdivisionMode::Uniform);
}

void TestSurfaceProject::plainHistoriesStayVersionOne()
{
    Timeline plain(
        TriangleMesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}});
    QCOMPARE(json::parse(projectJson(plain))["version"].get<int>(), 1);
    QVERIFY(!json::parse(projectJson(plain)).contains("surface"));
}

void TestSurfaceProject::versionOneFilesStillLoad()
{
    const Timeline loaded = loadProject(test::testDataPath("projects/v1_stroke_only.trimlab"));
    QCOMPARE(loaded.frameCount(), 2);
    QVERIFY(!loaded.hasSurface());
    QVERIFY(!loaded.frame(1).isControlEdit());
    QCOMPARE(loaded.frame(1).stroke.drag, glm::dvec3(0.0, 0.0, 0.5));
    QVERIFY(loaded.currentControlPoints().empty());
}

// The valid file the broken version-2 projects of tests/data/broken start from
// (make_broken_documents.py): its base mesh and its edit frame must be exactly what the
// surface gives, or the broken variants would test the wrong thing.
void TestSurfaceProject::versionTwoExampleLoads()
{
    const Timeline loaded = loadProject(test::testDataPath("projects/v2_cube_cage.trimlab"));
    QCOMPARE(loaded.frameCount(), 2);
    QVERIFY(loaded.hasSurface());
    QVERIFY(loaded.surface()->kind() == SurfaceKind::Subdivision);
    QVERIFY(loaded.frame(1).isControlEdit());
    QCOMPARE(loaded.frame(1).controlMoves.size(), std::size_t(1));
    QCOMPARE(loaded.frame(1).controlMoves[0].index, 2u);
    QCOMPARE(loaded.frame(1).controlMoves[0].after, glm::dvec3(1.0, 1.0, 0.5));
    EditableSurface surface(*loaded.surface());
    requireSurfaceMatchesTimeline(surface, loaded);
    QVERIFY(sameBytes(surface.mesh().positions, loaded.base().positions));
    surface.setControlPoints(loaded.currentControlPoints());
    QVERIFY(sameBytes(surface.mesh().positions, loaded.currentPositions()));
}

void TestSurfaceProject::malformedControlMovesGiveExactErrors_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("expected");
    const json good = json::parse(projectJson(subdivisionHistory()));
    const auto row = [&](const char* name, const std::function<void(json&)>& edit, const std::string& expected) {
        json document = good;
        edit(document);
        QTest::newRow(name) << QString::fromStdString(document.dump()) << QString::fromStdString(expected);
    };
    row(
        "before differs",
        [](json& d) {
            d["frames"][0]["control_moves"]["before"] = dvec3ArrayJson(std::vector<glm::dvec3>{{1.0, 1.0, 2.0}});
        },
        "p.trimlab: inconsistent history: frames[0]: control move 0: the 'before' position (1.000000, 1.000000, "
        "2.000000) of control point 2 differs from its current position (-1.000000, 1.000000, 1.000000)");
    row(
        "index out of range",
        [](json& d) { d["frames"][0]["control_moves"]["indices"] = uint32ArrayJson(std::vector<std::uint32_t>{8}); },
        "p.trimlab: inconsistent history: frames[0]: control move 0: control point 8 is out of range (the surface "
        "has 8 control points)");
    row(
        "length mismatch",
        [](json& d) {
            d["frames"][0]["control_moves"]["indices"] = uint32ArrayJson(std::vector<std::uint32_t>{2, 3});
        },
        "p.trimlab: frames[0].control_moves: lists 2 control points but 1 'before' and 1 'after' points");
    row(
        "no moves",
        [](json& d) { d["frames"][0]["control_moves"]["indices"] = uint32ArrayJson(std::vector<std::uint32_t>{}); },
        "p.trimlab: frames[0].control_moves.indices: must list at least one control point");
    row(
        "not float64",
        [](json& d) {
            d["frames"][0]["control_moves"]["after"] = positionArrayJson(std::vector<glm::vec3>{{0.0f, 1.0f, 1.0f}});
        },
        "p.trimlab: frames[0].control_moves.after.type: must be \"float64\", not \"float32\"");
    row(
        "stroke and moves",
        [](json& d) {
            d["frames"][0]["stroke"] = json{{"anchor", {0, 0, 0}}, {"drag", {0, 0, 0}}};
        },
        "p.trimlab: frames[0]: has both 'stroke' and 'control_moves'; a frame is one or the other");
    row(
        "no surface", [](json& d) { d.erase("surface"); },
        "p.trimlab: inconsistent history: frames[0]: a control-point edit needs a surface definition (this history "
        "has none)");
    row(
        "unknown kind", [](json& d) { d["surface"]["kind"] = "bezier"; },
        "p.trimlab: surface.kind: unknown value 'bezier' (known: nurbs, subdivision)");
    row(
        "level too deep", [](json& d) { d["surface"]["level"] = 6; },
        "p.trimlab: surface.level: must be an integer in [0, 5], not 6");
    row(
        "bad cage",
        [](json& d) {
            d["surface"]["face_sizes"] = uint32ArrayJson(std::vector<std::uint32_t>{4, 4, 4, 4, 4, 2});
        },
        "");
}

void TestSurfaceProject::malformedControlMovesGiveExactErrors()
{
    QFETCH(QString, text);
    QFETCH(QString, expected);
    const QString actual = QString::fromStdString(errorOf(text.toStdString()));
    if (expected.isEmpty()) // the cage validator's own wording: only the path is ours
        QVERIFY2(actual.startsWith("p.trimlab: surface: subdivision: "), qPrintable(actual));
    else
        QCOMPARE(actual, expected);
}

QTEST_GUILESS_MAIN(TestSurfaceProject)
#include "tst_surface_project.moc"
