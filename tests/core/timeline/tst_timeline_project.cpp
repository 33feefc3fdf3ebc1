// .trimlab project files: exact round trips, atomic replacement, and typed errors for
// damaged files that never leave a half-loaded timeline behind.
#include "project_load_error.h"
#include "test_paths.h"
#include "tst_timeline_fixtures.h"

#include "core/timeline/project_file.h"

#include <QtTest>

#include <fstream>
#include <limits>
#include <sstream>

using namespace trimlab;
using namespace trimlab::timeline;
using trimlab::test::frameTo;
using trimlab::test::gridMesh;

namespace {

std::string readAll(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

void writeAll(const std::filesystem::path& path, const std::string& text)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
}

std::filesystem::path freshDir(const char* name)
{
    const std::filesystem::path dir = test::outputDir() / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

// A mesh whose floats are awkward: inexact decimals, -0.0f, denormals, huge and tiny.
TriangleMesh awkwardMesh()
{
    TriangleMesh mesh = gridMesh(4);
    mesh.positions[0] = {0.1f, -0.0f, std::numeric_limits<float>::denorm_min()};
    mesh.positions[1] = {-std::numeric_limits<float>::denorm_min(), 3.4e38f, 1e-38f};
    mesh.positions[2].z = 1.0f / 3.0f;
    return mesh;
}

// Three sets (the last one empty), strokes with and without anchor triangles, doubles
// that need all 17 digits.
Timeline awkwardTimeline()
{
    Timeline t(awkwardMesh(), DynamicRule::ConstructiveAdditive);
    Frame a = frameTo(t, {0, 5}, {{-0.0f, 0.1f, 0.2f}, {std::numeric_limits<float>::denorm_min(), 0.7f, -0.0f}});
    a.stroke.anchor = {0.1, 1.0 / 3.0, -0.0};
    a.stroke.anchorTriangle = 7;
    a.stroke.drag = {5e-324, -1e308, 0.30000000000000004};
    a.stroke.brush.radius = 0.1 + 0.2;
    a.stroke.brush.strength = -1.5;
    a.stroke.brush.profile = deform::FalloffProfile::Sharp;
    a.stroke.brush.smoothingIterations = 0;
    a.stroke.brush.smoothingWeights = deform::SmoothingWeights::Cotangent;
    a.stroke.brush.smoothingStep = 1.0;
    t.appendFrame(a);
    t.startSet(DynamicRule::HomogeneousConfluent);
    t.appendFrame(frameTo(t, {0, 1, 15}, {{0.0f, 0.0f, 0.0f}, {1.0f, 2.0f, 3.0f}, {0.1f, 0.1f, 0.1f}}));
    t.appendFrame(frameTo(t, {}, {}));
    t.startSet(DynamicRule::ConstructiveIntersection);
    return t;
}

ProjectExtras someExtras()
{
    ProjectExtras extras;
    extras.view = ProjectView{{0.1, 0.2, 3.0000000000000004}, {0.0, -0.0, 0.5}, {0.0, 1.0, 0.0}, 37.5};
    extras.staticRule = StaticRule::AlternatingBorder;
    return extras;
}

ProjectFileError loadError(const std::string& text)
{
    return test::projectLoadError(text, "damaged.trimlab");
}

// Replaces the JSON value `"key": <old>` (first occurrence after `after`) by `value`.
std::string replaceValue(std::string text, const std::string& key, const std::string& value, std::size_t after = 0)
{
    const std::size_t at = text.find("\"" + key + "\":", after);
    Q_ASSERT(at != std::string::npos);
    const std::size_t begin = text.find(':', at) + 1;
    std::size_t end = begin;
    int depth = 0;
    for (; end < text.size(); ++end) {
        const char c = text[end];
        if (c == '[' || c == '{')
            ++depth;
        else if (c == ']' || c == '}') {
            if (depth == 0)
                break;
            --depth;
        } else if (c == ',' && depth == 0)
            break;
    }
    return text.substr(0, begin) + " " + value + text.substr(end);
}

// The example of docs/project-format.md, verbatim.
const char* const kDocumentedExample = R"({
 "base_mesh": {
  "positions": {"base64": "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA", "count": 9, "crc32": 2292412559, "type": "float32"},
  "triangles": {"base64": "AAAAAAEAAAACAAAA", "count": 3, "crc32": 494276218, "type": "uint32"}
 },
 "format": "trimlab-project",
 "frames": [
  {
   "after": {"base64": "AAAAAAAAgD8AAAA/", "count": 3, "crc32": 4034056413, "type": "float32"},
   "before": {"base64": "AAAAAAAAgD8AAAAA", "count": 3, "crc32": 1175780832, "type": "float32"},
   "stroke": {"anchor": [0.0, 1.0, 0.0], "drag": [0.0, 0.0, 0.5], "profile": "smooth", "radius": 0.25,
              "smoothing": {"iterations": 2, "step": 0.5, "weights": "uniform"}, "strength": 1.0, "triangle": 0},
   "vertices": {"base64": "AgAAAA==", "count": 1, "crc32": 2337085335, "type": "uint32"}
  }
 ],
 "generator": "TrimLab",
 "sets": [{"first_frame": 1, "frame_count": 1, "rule": "confluent"}],
 "static_rule": "alternating-border",
 "version": 1,
 "view": {"eye": [0.0, 0.0, 3.0], "fovy_degrees": 45.0, "target": [0.0, 0.0, 0.0], "up": [0.0, 1.0, 0.0]}
}
)";

} // namespace

class TestTimelineProject : public QObject {
    Q_OBJECT
private slots:
    void documentedExampleLoads();
    void roundTripIsBitExact();
    void roundTripWithoutExtras();
    void savingReplacesTheFileAtomically();
    void failedSaveLeavesTheOldFile();
    void truncatedFileIsReported();
    void flippedBase64ByteIsReported();
    void failedLoadLeavesCallersTimelineUntouched();
    void errorsNameTheProblem_data();
    void errorsNameTheProblem();
};

void TestTimelineProject::documentedExampleLoads()
{
    const Project project = parseProject(kDocumentedExample, "example.trimlab");
    const Timeline& t = project.timeline;
    QCOMPARE(t.base().positions, (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
    QCOMPARE(t.base().triangles, (std::vector<glm::uvec3>{{0, 1, 2}}));
    QCOMPARE(t.frameCount(), 2);
    QCOMPARE(t.positionsAt(1)[2], glm::vec3(0.0f, 1.0f, 0.5f));
    QCOMPARE(t.frame(1).stroke.anchorTriangle, std::optional<std::uint32_t>(0));
    QCOMPARE(t.frame(1).stroke.drag, glm::dvec3(0.0, 0.0, 0.5));
    QCOMPARE(t.sets().size(), std::size_t(1));
    QCOMPARE(t.sets()[0].rule, DynamicRule::Confluent);
    QCOMPARE(project.extras.staticRule, std::optional<StaticRule>(StaticRule::AlternatingBorder));
    QCOMPARE(project.extras.view, std::optional<ProjectView>(ProjectView{}));
}

void TestTimelineProject::roundTripIsBitExact()
{
    const Timeline original = awkwardTimeline();
    const std::filesystem::path path = freshDir("roundtrip") / "awkward.trimlab";
    saveProject(original, path, someExtras());
    const Project loaded = readProject(path);
    QCOMPARE(loaded.timeline, original);
    QVERIFY(test::sameBits(loaded.timeline, original));
    for (int f = 0; f < original.frameCount(); ++f)
        QVERIFY(test::sameBits(loaded.timeline.positionsAt(f), original.positionsAt(f)));
    QCOMPARE(loaded.extras, someExtras());
    QVERIFY(test::sameBits(loaded.extras.view->eye, someExtras().view->eye));
    QVERIFY(std::signbit(loaded.extras.view->target.y));
    QVERIFY(std::signbit(loaded.timeline.frame(1).stroke.anchor.z));
    // Saving what was loaded writes the same bytes.
    QCOMPARE(projectJson(loaded.timeline, loaded.extras), readAll(path));
}

void TestTimelineProject::roundTripWithoutExtras()
{
    const Timeline original(gridMesh(3));
    const Project loaded = parseProject(projectJson(original), "memory");
    QCOMPARE(loaded.timeline, original);
    QVERIFY(!loaded.extras.view);
    QVERIFY(!loaded.extras.staticRule);
    // Even a default-constructed timeline (no mesh, no sets) survives a round trip.
    QCOMPARE(parseProject(projectJson(Timeline()), "memory").timeline, Timeline());
}

// rename() replaces the directory entry: a reader that opened the old file keeps reading
// the complete old contents, and no temporary file is left behind.
void TestTimelineProject::savingReplacesTheFileAtomically()
{
    const std::filesystem::path dir = freshDir("atomic");
    const std::filesystem::path path = dir / "scene.trimlab";
    Timeline first(gridMesh(3));
    saveProject(first, path);
    const std::string firstBytes = readAll(path);
    std::ifstream oldReader(path, std::ios::binary);
    Timeline second = awkwardTimeline();
    saveProject(second, path);
    std::ostringstream oldContents;
    oldContents << oldReader.rdbuf();
    QCOMPARE(oldContents.str(), firstBytes);
    QCOMPARE(loadProject(path), second);
    int entries = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        QCOMPARE(entry.path().filename().string(), std::string("scene.trimlab"));
        ++entries;
    }
    QCOMPARE(entries, 1);
}

void TestTimelineProject::failedSaveLeavesTheOldFile()
{
    const std::filesystem::path dir = freshDir("failed-save");
    const std::filesystem::path path = dir / "scene.trimlab";
    saveProject(awkwardTimeline(), path);
    const std::string before = readAll(path);
    ProjectExtras bad;
    bad.view = ProjectView{};
    bad.view->fovyDegrees = std::numeric_limits<double>::quiet_NaN();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, saveProject(Timeline(gridMesh(3)), path, bad));
    QCOMPARE(readAll(path), before);
    // A folder is refused before anything is written (core/io/output_target.h): no
    // temporary file is left beside it.
    const std::filesystem::path folder = dir / "folder.trimlab";
    std::filesystem::create_directories(folder / "inside");
    try {
        saveProject(awkwardTimeline(), folder);
        QFAIL("saving over a folder should fail");
    } catch (const std::runtime_error& error) {
        QVERIFY2(QString(error.what()).contains("folder.trimlab is a folder; give a file name"), error.what());
    }
    QVERIFY(std::filesystem::is_directory(folder / "inside"));
    int entries = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        QVERIFY2(entry.path().filename().string().find(".tmp-") == std::string::npos, entry.path().c_str());
        ++entries;
    }
    QCOMPARE(entries, 2);
}

void TestTimelineProject::truncatedFileIsReported()
{
    const std::filesystem::path path = freshDir("truncated") / "cut.trimlab";
    const std::string text = projectJson(awkwardTimeline());
    for (const std::size_t length : {text.size() / 2, text.size() - 3, std::size_t(40)}) {
        writeAll(path, text.substr(0, length));
        try {
            (void)loadProject(path);
            QFAIL("a truncated project loaded");
        } catch (const ProjectFileError& error) {
            QCOMPARE(error.file(), path.string());
            QVERIFY2(error.reason().starts_with("truncated"), error.what());
        }
    }
}

void TestTimelineProject::flippedBase64ByteIsReported()
{
    const std::string text = projectJson(awkwardTimeline());
    // The payload of frames[0].after: the first "after" array after the first "frames".
    const std::size_t after = text.find("\"after\"", text.find("\"frames\""));
    const std::size_t payload = text.find("\"base64\": \"", after) + std::string("\"base64\": \"").size();
    QVERIFY(after != std::string::npos && payload > after);
    std::string damaged = text;
    char& c = damaged[payload + 2];
    c = c == 'A' ? 'B' : 'A'; // still valid base64, different bytes
    const ProjectFileError error = loadError(damaged);
    QCOMPARE(error.where(), std::string("frames[0].after"));
    QVERIFY2(error.reason().starts_with("CRC mismatch"), error.what());
    QVERIFY2(QString(error.what()).startsWith("damaged.trimlab: frames[0].after: CRC mismatch"), error.what());
    // A character outside the alphabet is reported as damaged base64.
    damaged[payload + 2] = '#';
    const ProjectFileError invalid = loadError(damaged);
    QCOMPARE(invalid.where(), std::string("frames[0].after.base64"));
    QVERIFY2(invalid.reason().find("not base64") != std::string::npos, invalid.what());
}

void TestTimelineProject::failedLoadLeavesCallersTimelineUntouched()
{
    const std::filesystem::path dir = freshDir("untouched");
    saveProject(awkwardTimeline(), dir / "good.trimlab");
    const std::string text = readAll(dir / "good.trimlab");
    writeAll(dir / "bad.trimlab", text.substr(0, text.size() - 10));
    Timeline current = loadProject(dir / "good.trimlab");
    const Timeline copy = current;
    try {
        current = loadProject(dir / "bad.trimlab");
        QFAIL("the damaged project loaded");
    } catch (const ProjectFileError&) {
    }
    QCOMPARE(current, copy);
    QVERIFY(test::sameBits(current, copy));
}

void TestTimelineProject::errorsNameTheProblem_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("where");
    QTest::addColumn<QString>("reason");
    const std::string good = projectJson(awkwardTimeline(), someExtras());
    const auto row = [](const char* name, const std::string& text, const char* where, const char* reason) {
        QTest::newRow(name) << QString::fromStdString(text) << where << reason;
    };
    row("empty", "", "", "not a TrimLab project: invalid JSON at line 1, column 1: the document is empty");
    row("not json", "solid cube\nfacet normal", "", "not a TrimLab project: invalid JSON at line 1");
    row("a glTF file", R"({"asset": {"version": "2.0"}})", "", "not a TrimLab project");
    row("an array", "[1, 2]", "", "not a TrimLab project");
    row("newer version", replaceValue(good, "version", "7"), "", "version 7 is newer than this TrimLab (3)");
    row("version zero", replaceValue(good, "version", "0"), "version", "must be an integer in [1, ");
    const std::size_t secondRule = good.find("\"rule\"", good.find("\"rule\"", good.find("\"sets\"")) + 1);
    row("unknown rule", replaceValue(good, "rule", "\"foo\"", secondRule), "sets[1].rule", "unknown rule 'foo'");
    row("frames not an array", replaceValue(good, "frames", "null"), "frames", "must be an array, not null");
    std::string noVersion = good;
    noVersion.replace(good.find("\"version\""), 9, "\"versio\"");
    row("missing version", noVersion, "", "missing field 'version'");
    row("sets disagree with frames", replaceValue(good, "frame_count", "2"), "",
        "inconsistent history: sets[1]: starts at frame 2, expected 3");
    row("negative radius", replaceValue(good, "radius", "-1"), "frames[0].stroke.radius", "must be > 0");
    row("unknown profile", replaceValue(good, "profile", "\"soft\""), "frames[0].stroke.profile",
        "unknown profile 'soft'");
    row("unknown static rule", replaceValue(good, "static_rule", "\"odd\""), "static_rule",
        "unknown static rule 'odd'");
    row("count disagrees", replaceValue(good, "count", "47"), "base_mesh.positions", "holds 192 bytes, but count 47");
    row("wrong array type", replaceValue(good, "type", "\"float64\""), "base_mesh.positions.type",
        "must be \"float32\"");
    row("too deep", std::string(200, '[') + std::string(200, ']'), "",
        "not a TrimLab project: invalid JSON at line 1, column 65");
    // A number beyond the double range is refused by the JSON library in another way than
    // a syntax error; it must still be a ProjectFileError naming the number and its place.
    row("number overflow", "{\"format\": 1e999}", "",
        "not a TrimLab project: invalid JSON at line 1, column 12: the number 1e999 does not fit a double");
}

void TestTimelineProject::errorsNameTheProblem()
{
    QFETCH(QString, text);
    QFETCH(QString, where);
    QFETCH(QString, reason);
    const ProjectFileError error = loadError(text.toStdString());
    QVERIFY2(QString::fromStdString(error.where()) == where, error.what());
    QVERIFY2(QString::fromStdString(error.reason()).startsWith(reason), error.what());
    QCOMPARE(error.file(), std::string("damaged.trimlab"));
}

QTEST_GUILESS_MAIN(TestTimelineProject)
#include "tst_timeline_project.moc"
