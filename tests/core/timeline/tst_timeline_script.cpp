// Stroke scripts: parsing with errors that name the JSON path, exact write/parse round
// trips, and replay: timeline -> script -> replay reproduces every frame bit for bit.
#include "test_paths.h"
#include "tst_timeline_fixtures.h"

#include "core/timeline/stroke_replay.h"
#include "core/timeline/stroke_script.h"

#include <QtTest>

#include <stop_token>

using namespace trimlab;
using namespace trimlab::timeline;
using trimlab::test::gridMesh;

namespace {

const char* const kExample = R"({
  "format": "trimlab-stroke-script",
  "version": 1,
  "sets": [
    {"rule": "additive", "strokes": [
      {"anchor": [0.5, 0.5, 0.0], "drag": [0.0, 0.0, 0.25], "radius": 0.3},
      {"anchor": [0.21, 0.3, 0.0], "triangle": 127, "drag": [0.05, 0.0, -0.1], "radius": 0.25,
       "strength": 0.5, "profile": "linear",
       "smoothing": {"iterations": 3, "weights": "cotangent", "step": 0.25}}
    ]},
    {"rule": "confluent", "strokes": [
      {"anchor": [0.7, 0.6, 0.1], "drag": [0.0, 0.1, 0.2], "radius": 0.35, "profile": "sharp"}
    ]},
    {"rule": "subtractive", "strokes": [
      {"anchor": [0.4, 0.7, 0.0], "drag": [0.0, 0.0, -0.2], "radius": 0.3}
    ]}
  ]
})";

StrokeScriptError parseError(const std::string& text)
{
    try {
        (void)parseStrokeScript(text, "s.json");
    } catch (const StrokeScriptError& error) {
        return error;
    }
    return StrokeScriptError("s.json", "", "<parsed without an error>");
}

// kExample with the text `from` replaced by `to` (once).
std::string edited(const std::string& from, const std::string& to)
{
    std::string text = kExample;
    const std::size_t at = text.find(from);
    Q_ASSERT(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

} // namespace

class TestTimelineScript : public QObject {
    Q_OBJECT
private slots:
    void parsesTheDocumentedExample();
    void errorsNameTheJsonPath_data();
    void errorsNameTheJsonPath();
    void syntaxErrorsGiveLineAndColumn();
    void writeThenParseIsBitExact();
    void replayBuildsTheTimeline();
    void timelineScriptReplayRoundTrip();
    void replayReportsBadStrokesAndCancels();
};

void TestTimelineScript::parsesTheDocumentedExample()
{
    const StrokeScript script = parseStrokeScript(kExample, "example.json");
    QCOMPARE(script.sets.size(), std::size_t(3));
    QCOMPARE(script.strokeCount(), std::size_t(4));
    QCOMPARE(script.sets[0].rule, DynamicRule::ConstructiveAdditive);
    QCOMPARE(script.sets[1].rule, DynamicRule::Confluent);
    QCOMPARE(script.sets[2].rule, DynamicRule::ConstructiveSubtractive);
    const deform::Stroke& plain = script.sets[0].strokes[0];
    QCOMPARE(plain.anchor, glm::dvec3(0.5, 0.5, 0.0));
    QVERIFY(!plain.anchorTriangle);
    QCOMPARE(plain.drag, glm::dvec3(0.0, 0.0, 0.25));
    deform::BrushSettings defaults;
    defaults.radius = 0.3;
    QCOMPARE(plain.brush, defaults); // omitted fields take BrushSettings' defaults
    const deform::Stroke& full = script.sets[0].strokes[1];
    QCOMPARE(full.anchorTriangle, std::optional<std::uint32_t>(127));
    QCOMPARE(full.brush.strength, 0.5);
    QCOMPARE(full.brush.profile, deform::FalloffProfile::Linear);
    QCOMPARE(full.brush.smoothingIterations, 3);
    QCOMPARE(full.brush.smoothingWeights, deform::SmoothingWeights::Cotangent);
    QCOMPARE(full.brush.smoothingStep, 0.25);
    QCOMPARE(script.sets[1].strokes[0].brush.profile, deform::FalloffProfile::Sharp);
}

void TestTimelineScript::errorsNameTheJsonPath_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("message");
    const auto row = [](const char* name, const std::string& text, const char* message) {
        QTest::newRow(name) << QString::fromStdString(text) << message;
    };
    row("radius zero", edited("\"radius\": 0.25", "\"radius\": 0"), "s.json: sets[0].strokes[1].radius: must be > 0");
    row("radius text", edited("\"radius\": 0.35", "\"radius\": \"big\""),
        "s.json: sets[1].strokes[0].radius: must be a number, not a string");
    row("step too big", edited("\"step\": 0.25", "\"step\": 1.5"),
        "s.json: sets[0].strokes[1].smoothing.step: must be in (0, 1]");
    row("negative iterations", edited("\"iterations\": 3", "\"iterations\": -1"),
        "s.json: sets[0].strokes[1].smoothing.iterations: must be an integer in [0, 10000], not -1");
    row("fractional triangle", edited("\"triangle\": 127", "\"triangle\": 4.5"),
        "s.json: sets[0].strokes[1].triangle: must be an integer in [0, 4294967295], not a number");
    row("unknown profile", edited("\"profile\": \"sharp\"", "\"profile\": \"soft\""),
        "s.json: sets[1].strokes[0].profile: unknown profile 'soft' (known: smooth, linear, sharp)");
    row("unknown weights", edited("\"cotangent\"", "\"cot\""),
        "s.json: sets[0].strokes[1].smoothing.weights: unknown smoothing weights 'cot' (known: uniform, cotangent)");
    row("unknown rule", edited("\"subtractive\"", "\"foo\""), "s.json: sets[2].rule: unknown rule 'foo'");
    row("typo in a field", edited("\"strength\"", "\"strenght\""),
        "s.json: sets[0].strokes[1].strenght: unknown field (known fields: anchor, triangle, drag");
    row("missing drag", edited("\"drag\": [0.0, 0.0, -0.2], ", ""), "s.json: sets[2].strokes[0]: missing field 'drag'");
    row("short anchor", edited("[0.7, 0.6, 0.1]", "[0.7, 0.6]"),
        "s.json: sets[1].strokes[0].anchor: must be an array of 3 numbers [x, y, z]");
    row("anchor component", edited("[0.7, 0.6, 0.1]", "[0.7, null, 0.1]"),
        "s.json: sets[1].strokes[0].anchor[1]: must be a number, not null");
    row("unknown set field",
        edited("\"strokes\": [\n      {\"anchor\": [0.7", "\"strokes\": 3, \"x\": [{\"anchor\": [0.7"),
        "s.json: sets[1].x: unknown field (known fields: rule, strokes)");
    row("wrong format", edited("trimlab-stroke-script", "trimlab-project"),
        "s.json: format: must be \"trimlab-stroke-script\", not \"trimlab-project\"");
    row("newer version", edited("\"version\": 1", "\"version\": 2"),
        "s.json: version: version 2 is newer than this TrimLab (1)");
    row("no sets", R"({"format": "trimlab-stroke-script", "version": 1, "sets": []})",
        "s.json: sets: must hold at least one set");
    row("not an object", "[]", "s.json: must be an object, not an array");
}

void TestTimelineScript::errorsNameTheJsonPath()
{
    QFETCH(QString, text);
    QFETCH(QString, message);
    const StrokeScriptError error = parseError(text.toStdString());
    QVERIFY2(QString(error.what()).startsWith(message), error.what());
    QCOMPARE(error.source(), std::string("s.json"));
    QVERIFY(!error.line());
}

void TestTimelineScript::syntaxErrorsGiveLineAndColumn()
{
    const StrokeScriptError error = parseError(edited("\"radius\": 0.35", "\"radius\": 0.35,"));
    QVERIFY2(error.line().has_value(), error.what());
    QCOMPARE(*error.line(), std::size_t(12));
    QVERIFY2(QString(error.what()).startsWith("s.json:12:"), error.what());
    QVERIFY2(error.reason().starts_with("invalid JSON: "), error.what());
    const StrokeScriptError cut = parseError(std::string(kExample).substr(0, 200));
    QVERIFY2(cut.reason().starts_with("truncated JSON: "), cut.what());
    QVERIFY_THROWS_EXCEPTION(StrokeScriptError, (void)loadStrokeScript(test::outputDir() / "no-such-script.json"));
}

void TestTimelineScript::writeThenParseIsBitExact()
{
    StrokeScript script = parseStrokeScript(kExample, "example.json");
    deform::Stroke& s = script.sets[1].strokes[0];
    s.anchor = {0.1, 1.0 / 3.0, -0.0};
    s.drag = {5e-324, -1e308, 0.30000000000000004};
    s.brush.radius = 0.1 + 0.2;
    s.brush.strength = 2.0 / 3.0;
    script.sets.push_back(ScriptSet{DynamicRule::HomogeneousConfluent, {}});
    const std::filesystem::path path = test::outputDir() / "written-script.json";
    writeStrokeScript(path, script);
    const StrokeScript read = loadStrokeScript(path);
    QCOMPARE(read.sets.size(), script.sets.size());
    for (std::size_t i = 0; i < script.sets.size(); ++i) {
        QCOMPARE(read.sets[i].rule, script.sets[i].rule);
        QCOMPARE(read.sets[i].strokes, script.sets[i].strokes);
    }
    const deform::Stroke& r = read.sets[1].strokes[0];
    QVERIFY(test::sameBits(r.anchor, s.anchor));
    QVERIFY(test::sameBits(r.drag, s.drag));
    QVERIFY(test::sameBits(r.brush.radius, s.brush.radius));
    QVERIFY(test::sameBits(r.brush.strength, s.brush.strength));
}

void TestTimelineScript::replayBuildsTheTimeline()
{
    const TriangleMesh base = gridMesh(16);
    const StrokeScript script = parseStrokeScript(kExample, "example.json");
    const Timeline t = replayStrokeScript(base, script);
    QCOMPARE(t.frameCount(), 5);
    QCOMPARE(t.sets().size(), std::size_t(3));
    QCOMPARE(t.sets()[0].rule, DynamicRule::ConstructiveAdditive);
    QCOMPARE(t.sets()[0].frameCount, 2);
    QCOMPARE(t.sets()[1].rule, DynamicRule::Confluent);
    QCOMPARE(t.sets()[1].referenceFrame(), 2);
    QCOMPARE(t.sets()[2].rule, DynamicRule::ConstructiveSubtractive);
    QCOMPARE(t.sets()[2].referenceFrame(), 3);
    for (int f = 1; f < t.frameCount(); ++f) {
        const Frame& frame = t.frame(f);
        QVERIFY2(frame.stroke.anchorTriangle.has_value(), "the recorded stroke is resolved");
        QVERIFY2(!frame.vertices.empty(), qPrintable(QString("stroke %1 moved nothing").arg(f)));
        // Recorded vertices are exactly those whose bits changed.
        const std::vector<glm::vec3> before = t.positionsAt(f - 1);
        const std::vector<glm::vec3> after = t.positionsAt(f);
        std::size_t changed = 0;
        for (std::size_t v = 0; v < before.size(); ++v)
            changed += test::sameBits(std::span(&before[v], 1), std::span(&after[v], 1)) ? 0 : 1;
        QCOMPARE(changed, frame.vertices.size());
    }
    // Deterministic: a second replay is identical.
    QCOMPARE(replayStrokeScript(base, script), t);
}

void TestTimelineScript::timelineScriptReplayRoundTrip()
{
    const TriangleMesh base = gridMesh(16);
    const Timeline recorded = replayStrokeScript(base, parseStrokeScript(kExample, "example.json"));
    const std::string text = strokeScriptJson(strokeScriptFromTimeline(recorded));
    const Timeline replayed = replayStrokeScript(base, parseStrokeScript(text, "recorded.json"));
    QCOMPARE(replayed.frameCount(), recorded.frameCount());
    QCOMPARE(replayed.sets(), recorded.sets());
    for (int f = 0; f < recorded.frameCount(); ++f)
        QVERIFY2(test::sameBits(replayed.positionsAt(f), recorded.positionsAt(f)),
                 qPrintable(QString("frame %1").arg(f)));
    QCOMPARE(replayed, recorded);
    QVERIFY(test::sameBits(replayed, recorded));
}

void TestTimelineScript::replayReportsBadStrokesAndCancels()
{
    const TriangleMesh base = gridMesh(16);
    StrokeScript script = parseStrokeScript(kExample, "example.json");
    script.sets[2].strokes[0].anchorTriangle = 100000;
    try {
        (void)replayStrokeScript(base, script, {}, "bad.json");
        QFAIL("a stroke on a missing triangle replayed");
    } catch (const StrokeScriptError& error) {
        QCOMPARE(error.path(), std::string("sets[2].strokes[0]"));
        QVERIFY2(QString(error.what()).startsWith("bad.json: sets[2].strokes[0]: "), error.what());
    }
    script.sets[2].strokes[0].anchorTriangle.reset();
    std::vector<std::size_t> done;
    std::stop_source stop;
    TaskControl control;
    control.stop = stop.get_token();
    control.progress = [&](const TaskProgress& p) {
        QCOMPARE(p.total, std::size_t(4));
        done.push_back(p.done);
        if (p.done == 2)
            stop.request_stop();
    };
    QVERIFY_THROWS_EXCEPTION(OperationCancelled, (void)replayStrokeScript(base, script, control));
    QCOMPARE(done, (std::vector<std::size_t>{0, 1, 2}));
}

QTEST_GUILESS_MAIN(TestTimelineScript)
#include "tst_timeline_script.moc"
