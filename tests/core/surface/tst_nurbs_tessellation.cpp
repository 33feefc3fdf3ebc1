// NURBS tessellation (core/surface/nurbs_tessellation.h), its sparse re-evaluation, the
// JSON format (nurbs_json.h, docs/nurbs-json.md) and OBJ export (mesh/obj_writer.h).
// Closed primitives must tessellate into closed, manifold, outward meshes (the trim
// rules need them); a control-point edit must move exactly the reported vertices and
// agree with evaluation from scratch.
#include "core/mesh/mesh_io.h"
#include "core/mesh/mesh_validation.h"
#include "core/mesh/obj_writer.h"
#include "core/surface/nurbs_json.h"
#include "core/surface/nurbs_primitives.h"
#include "core/surface/nurbs_tessellation.h"

#include "test_paths.h"

#include <QtTest>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstring>
#include <set>

using namespace trimlab;

namespace {

const glm::dvec3 kCenter(0.5, 1.0, -2.0);

struct ClosedCase {
    const char* name;
    NurbsSurface surface;
    std::int64_t genus;
    double volume; // analytic
};

std::vector<ClosedCase> closedCases()
{
    const double pi = M_PI;
    return {{"sphere", makeNurbsSphere(kCenter, 1.5), 0, 4.0 / 3.0 * pi * 1.5 * 1.5 * 1.5},
            {"torus", makeNurbsTorus(kCenter, 2.0, 0.5), 1, 2.0 * pi * pi * 2.0 * 0.5 * 0.5},
            {"capped tube", makeNurbsCappedTube(kCenter, 0.75, 2.0), 0, pi * 0.75 * 0.75 * 2.0}};
}

bool bitwiseEqual(const glm::dvec3& a, const glm::dvec3& b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// Bilinear 2×2 surface JSON with `replace` applied, for malformed-file tests.
std::string smallDocument(const std::string& from = {}, const std::string& to = {})
{
    std::string text = R"({"format": "trimlab-nurbs", "version": 1, "surfaces": [{"name": "quad",
 "degreeU": 1, "degreeV": 1, "countU": 2, "countV": 2, "closedU": false, "closedV": false,
 "knotsU": [0, 0, 1, 1], "knotsV": [0, 0, 1, 1],
 "points": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]],
 "weights": [1, 1, 1, 1]}]})";
    if (!from.empty()) {
        const std::size_t at = text.find(from);
        if (at == std::string::npos)
            qFatal("smallDocument: '%s' not found", from.c_str());
        text.replace(at, from.size(), to);
    }
    return text;
}

QString loadError(const std::string& text)
{
    try {
        (void)parseNurbsJson(text, "bad.json");
    } catch (const NurbsFileError& error) {
        return QString::fromStdString(error.what());
    }
    return "accepted";
}

} // namespace

class TestNurbsTessellation : public QObject {
    Q_OBJECT

private slots:
    void closedPrimitivesAreClosedManifoldOutward()
    {
        for (const ClosedCase& c : closedCases())
            for (const auto& [su, sv] : {std::pair{3, 1}, std::pair{8, 4}, std::pair{24, 12}, std::pair{128, 64}}) {
                const NurbsTessellation t(c.surface, su, sv);
                const MeshValidationReport report = validateMesh(t.mesh());
                const QString what = QString("%1 at %2×%3: ").arg(c.name).arg(su).arg(sv);
                QVERIFY2(report.closed(), qPrintable(what + QString::fromStdString(report.trimUnavailableReason())));
                QVERIFY2(report.manifold(), qPrintable(what + "not manifold"));
                QVERIFY2(report.trimmable(), qPrintable(what + QString::fromStdString(report.trimUnavailableReason())));
                QVERIFY2(!report.inconsistentEdges.any() && !report.degenerateFaces.any() &&
                             !report.unreferencedVertices.any(),
                         qPrintable(what + "defects"));
                QCOMPARE(report.componentCount, std::size_t(1));
                QCOMPARE(report.genus.value_or(-1), c.genus);
                QVERIFY2(report.signedVolume > 0.0, qPrintable(what + "inward"));
                // The inscribed polyhedron converges to the solid. The rational quarter arc is
                // not uniform in angle: at 16 intervals per quarter its largest step is 0.1035
                // rad, at 32 0.0518 rad, and a chord of angle θ loses at most θ²/6 of the
                // cross-section: 1.8e-3 + 0.45e-3 for the torus at 128×64 (16 intervals per
                // quarter of its minor circle), less for the others.
                if (su >= 128)
                    QVERIFY2(
                        std::abs(report.signedVolume - c.volume) <= 2.5e-3 * c.volume,
                        qPrintable(what + QString("volume %1, analytic %2").arg(report.signedVolume).arg(c.volume)));
                // No two vertices coincide: seams and poles share their vertices.
                std::set<std::tuple<float, float, float>> distinct;
                for (const glm::vec3& p : t.mesh().positions)
                    distinct.insert({p.x, p.y, p.z});
                QCOMPARE(distinct.size(), t.mesh().vertexCount());
            }
    }

    void countsAsDesigned()
    {
        // Worked out by hand from the sampling rule (nurbs_tessellation.h).
        const NurbsTessellation sphere(makeNurbsSphere(kCenter, 1.0), 16, 8);
        QCOMPARE(sphere.parametersU().size(), std::size_t(17));
        QCOMPARE(sphere.parametersV().size(), std::size_t(9));
        QCOMPARE(sphere.mesh().vertexCount(), std::size_t(16 * 7 + 2));
        QCOMPARE(sphere.mesh().triangleCount(), std::size_t(2 * 16 * 7));
        const NurbsTessellation torus(makeNurbsTorus(kCenter, 2.0, 1.0), 16, 12);
        QCOMPARE(torus.mesh().vertexCount(), std::size_t(16 * 12));
        QCOMPARE(torus.mesh().triangleCount(), std::size_t(2 * 16 * 12));
        const NurbsTessellation tube(makeNurbsCappedTube(kCenter, 1.0, 1.0), 12, 9);
        QCOMPARE(tube.parametersV(), (std::vector<double>{0, 1.0 / 3, 2.0 / 3, 1, 1 + 1.0 / 3, 1 + 2.0 / 3, 2,
                                                          2 + 1.0 / 3, 2 + 2.0 / 3, 3}));
        QCOMPARE(tube.mesh().vertexCount(), std::size_t(12 * 8 + 2));
        QCOMPARE(tube.mesh().triangleCount(), std::size_t(2 * 12 * 8));
        // The rims are knots, hence sample lines: the tessellated rims lie exactly on the
        // cylinder's ends.
        const NurbsTessellation cylinder(makeNurbsCylinder(kCenter, 1.0, 2.0), 12, 5);
        QCOMPARE(cylinder.mesh().vertexCount(), std::size_t(12 * 6));
        QCOMPARE(cylinder.mesh().triangleCount(), std::size_t(2 * 12 * 5));
        const MeshValidationReport open = validateMesh(cylinder.mesh());
        QCOMPARE(open.boundaryEdges.count, std::size_t(24));
        QVERIFY(open.manifold() && !open.inconsistentEdges.any());
        // Patch 7×5 bicubic: 4 spans of 0.25 → round(10·0.25) = 3 each; 2 spans → 4 each.
        const NurbsTessellation patch(makeNurbsPatch(kCenter, 2.0, 1.0, 7, 5), 10, 8);
        QCOMPARE(patch.mesh().vertexCount(), std::size_t(13 * 9));
        QCOMPARE(patch.mesh().triangleCount(), std::size_t(2 * 12 * 8));
        QCOMPARE(validateMesh(patch.mesh()).boundaryEdges.count, std::size_t(2 * (12 + 8)));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, NurbsTessellation(makeNurbsPatch(kCenter, 1, 1, 4, 4), 0, 4));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 NurbsTessellation(makeNurbsPatch(kCenter, 1, 1, 4, 4), 4, 9000));
    }

    void verticesAreExactEvaluations()
    {
        const NurbsSurface sphere = makeNurbsSphere(kCenter, 1.5);
        const NurbsTessellation t(sphere, 32, 16);
        for (std::uint32_t v = 0; v < t.mesh().vertexCount(); ++v) {
            const glm::dvec2 uv = t.vertexParameters(v);
            const glm::dvec3 p = evaluateNurbsPoint(sphere, uv.x, uv.y);
            QVERIFY(bitwiseEqual(t.positionsDouble()[v], p));
            QCOMPARE(t.mesh().positions[v], glm::vec3(p));
            QVERIFY(std::abs(glm::length(p - kCenter) - 1.5) <= 1e-9 * 1.5);
            // Outward unit normals, the poles included.
            const glm::dvec3 n(t.normals()[v]);
            QVERIFY(std::abs(glm::length(n) - 1.0) <= 1e-6);
            QVERIFY2(glm::dot(n, glm::normalize(p - kCenter)) >= 1.0 - 1e-6,
                     qPrintable(QString("vertex %1 (pole: %2)").arg(v).arg(t.isPoleVertex(v))));
        }
        // Torus and capped tube: regular vertex normals are the evaluator's; the tube's
        // cap centres (poles) get the cap planes' normals.
        for (const NurbsSurface& other : {makeNurbsTorus(kCenter, 2.0, 0.5), makeNurbsCappedTube(kCenter, 1.0, 2.0)}) {
            const NurbsTessellation o(other, 24, 12);
            for (std::uint32_t v = 0; v < o.mesh().vertexCount(); ++v) {
                const glm::dvec2 uv = o.vertexParameters(v);
                const glm::dvec3 n(o.normals()[v]);
                if (!o.isPoleVertex(v)) {
                    QVERIFY(glm::dot(n, nurbsNormal(other, uv.x, uv.y)) >= 1.0 - 1e-6);
                    continue;
                }
                const glm::dvec3 expected(0.0, uv.y == 0.0 ? -1.0 : 1.0, 0.0);
                QVERIFY2(glm::dot(n, expected) >= 1.0 - 1e-6, qPrintable(QString::fromStdString(other.name)));
            }
        }
        QVERIFY(t.isPoleVertex(t.vertexOfSample(5, 0)));
        QCOMPARE(t.vertexOfSample(5, 0), t.vertexOfSample(0, 0));
        QCOMPARE(t.vertexOfSample(32, 7), t.vertexOfSample(0, 7)); // the seam
    }

    void editMovesExactlyTheSupport_data()
    {
        QTest::addColumn<int>("shape"); // 0 sphere, 1 torus, 2 capped tube, 3 patch
        QTest::addColumn<int>("i");
        QTest::addColumn<int>("j");
        QTest::addColumn<bool>("weight");
        QTest::newRow("sphere inner") << 0 << 3 << 2 << false;
        QTest::newRow("sphere seam") << 0 << 8 << 1 << false;
        QTest::newRow("sphere pole") << 0 << 4 << 0 << false;
        QTest::newRow("sphere weight") << 0 << 5 << 3 << true;
        QTest::newRow("torus corner") << 1 << 0 << 0 << false;
        QTest::newRow("torus seam weight") << 1 << 0 << 5 << true;
        QTest::newRow("tube rim") << 2 << 2 << 1 << false;
        QTest::newRow("tube top pole") << 2 << 7 << 3 << false;
        QTest::newRow("patch corner") << 3 << 0 << 0 << false;
        QTest::newRow("patch inner") << 3 << 3 << 2 << false;
    }

    void editMovesExactlyTheSupport()
    {
        QFETCH(int, shape);
        QFETCH(int, i);
        QFETCH(int, j);
        QFETCH(bool, weight);
        NurbsSurface s = shape == 0   ? makeNurbsSphere(kCenter, 1.0)
                         : shape == 1 ? makeNurbsTorus(kCenter, 2.0, 0.5)
                         : shape == 2 ? makeNurbsCappedTube(kCenter, 1.0, 2.0)
                                      : makeNurbsPatch(kCenter, 2.0, 2.0, 7, 6);
        NurbsTessellation t(s, 40, 21);
        const NurbsTessellation before = t;
        const std::size_t k = s.index(i, j);
        if (weight)
            setControlWeight(s, k, 3.0 * s.weights[k]);
        else
            moveControlPoint(s, k, s.points[k] + glm::dvec3(0.3, -0.2, 0.45));
        const std::size_t changed[] = {k};
        const std::vector<std::uint32_t> moved = t.update(s, changed);
        QCOMPARE(moved, t.support(k));
        QVERIFY(!moved.empty());
        QVERIFY(moved.size() < t.mesh().vertexCount());
        // Exactly the support moved (in double and in float); nothing else changed.
        const std::set<std::uint32_t> inSupport(moved.begin(), moved.end());
        for (std::uint32_t v = 0; v < t.mesh().vertexCount(); ++v) {
            const bool same = bitwiseEqual(t.positionsDouble()[v], before.positionsDouble()[v]);
            QVERIFY2(same != bool(inSupport.count(v)), qPrintable(QString("vertex %1").arg(v)));
            // In float, a vertex at the edge of the support may move by less than half an
            // ulp (weights there are ~1e-8); a float change still implies the support.
            if (t.mesh().positions[v] != before.mesh().positions[v])
                QVERIFY(inSupport.count(v));
        }
        // The sparse update equals a tessellation built from scratch, bitwise.
        const NurbsTessellation fresh(s, 40, 21);
        QCOMPARE(t.mesh(), fresh.mesh());
        QCOMPARE(t.normals(), fresh.normals());
        for (std::uint32_t v = 0; v < t.mesh().vertexCount(); ++v)
            QVERIFY(bitwiseEqual(t.positionsDouble()[v], fresh.positionsDouble()[v]));
        // ...and a full update.
        NurbsTessellation full = before;
        full.update(s);
        QCOMPARE(full.mesh(), fresh.mesh());
        QCOMPARE(full.normals(), fresh.normals());
    }

    void moveEverythingSparse()
    {
        NurbsSurface s = makeNurbsTorus(kCenter, 2.0, 0.7);
        NurbsTessellation t(s, 48, 24);
        std::vector<std::size_t> all;
        for (std::size_t k = 0; k < s.points.size(); ++k) {
            s.points[k] = 1.1 * s.points[k] + glm::dvec3(0.01 * double(k % 7), 0.0, 0.0);
            all.push_back(k);
        }
        // Re-tie the seams (the edit above moved twins alike except for k % 7).
        for (int jj = 0; jj < s.countV; ++jj)
            s.points[s.index(s.countU - 1, jj)] = s.points[s.index(0, jj)];
        for (int ii = 0; ii < s.countU; ++ii)
            s.points[s.index(ii, s.countV - 1)] = s.points[s.index(ii, 0)];
        QCOMPARE(t.update(s, all).size(), t.mesh().vertexCount());
        const NurbsTessellation fresh(s, 48, 24);
        QCOMPARE(t.mesh(), fresh.mesh());
        QCOMPARE(t.normals(), fresh.normals());
        QVERIFY(validateMesh(t.mesh()).closed());
    }

    void brokenTiesAndShapesRefused()
    {
        NurbsSurface s = makeNurbsSphere(kCenter, 1.0);
        NurbsTessellation t(s, 16, 8);
        const TriangleMesh before = t.mesh();
        NurbsSurface splitPole = s;
        splitPole.points[splitPole.index(3, 0)] += glm::dvec3(0.1, 0, 0);
        QVERIFY(!t.matches(splitPole));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, t.update(splitPole));
        NurbsSurface openSeam = s;
        openSeam.points[openSeam.index(0, 2)] += glm::dvec3(0.1, 0, 0);
        const std::size_t changed[] = {openSeam.index(0, 2)};
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, t.update(openSeam, changed));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, t.update(makeNurbsTorus(kCenter, 2.0, 1.0)));
        const std::size_t outOfRange[] = {45};
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, t.update(s, outOfRange));
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, (void)t.support(45));
        QCOMPARE(t.mesh(), before);
    }

    void jsonRoundTripIsBitExact()
    {
        NurbsSurface patch = makeNurbsPatch(kCenter, 3.0, 2.0, 6, 5);
        patch.name = "wavy \"patch\" ü";
        for (std::size_t k = 0; k < patch.points.size(); ++k) {
            patch.points[k].y = std::sin(double(k)) * 0.1 + 1e-300 * double(k); // awkward doubles
            patch.weights[k] = 0.1 + 0.2 * double(k % 3) + 1.0 / 3.0;
        }
        patch.knotsU = {0, 0, 0, 0, 0.1 + 0.2, 2.0 / 3.0, 1, 1, 1, 1};
        const std::vector<NurbsSurface> surfaces{makeNurbsSphere(kCenter, 1.0 / 3.0), makeNurbsTorus(kCenter, 2, 0.3),
                                                 makeNurbsCappedTube(kCenter, 1, 2), patch};
        const std::filesystem::path path = test::outputDir() / "round_trip.nurbs.json";
        saveNurbsJson(path, surfaces);
        const std::vector<NurbsSurface> loaded = loadNurbsJson(path);
        QCOMPARE(loaded.size(), surfaces.size());
        for (std::size_t k = 0; k < surfaces.size(); ++k) {
            QVERIFY(loaded[k] == surfaces[k]);
            QVERIFY(std::memcmp(loaded[k].points.data(), surfaces[k].points.data(),
                                surfaces[k].points.size() * sizeof(glm::dvec3)) == 0);
            QVERIFY(std::memcmp(loaded[k].weights.data(), surfaces[k].weights.data(),
                                surfaces[k].weights.size() * sizeof(double)) == 0);
        }
        QCOMPARE(nurbsJson(loaded), nurbsJson(surfaces));
    }

    void malformedJsonRefused_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("message");
        const auto row = [](const char* name, const std::string& text, const char* message) {
            QTest::newRow(name) << QString::fromStdString(text) << QString(message);
        };
        row("knots decrease", smallDocument("\"knotsU\": [0, 0, 1, 1]", "\"knotsU\": [0, 0.75, 0.5, 1]"),
            "bad.json: surfaces[0].knotsU[2]: knots must not decrease (0.5 after 0.75); sort the knot vector");
        row("not clamped", smallDocument("\"knotsV\": [0, 0, 1, 1]", "\"knotsV\": [0, 0.5, 1, 1]"),
            "bad.json: surfaces[0].knotsV[1]: the first 2 knots must be equal (clamped knot vector); repeat the first "
            "knot degree+1 times");
        row("infinite coordinate", smallDocument("[1, 1, 0]", "[1, 1, 1e999]"),
            "bad.json: invalid JSON at line 4, column 53: the number 1e999 does not fit a double; use finite values");
        row("nan", smallDocument("[1, 1, 0]", "[1, NaN, 0]"),
            // Column 50 is the N; the reason is nlohmann's.
            "bad.json: invalid JSON at line 4, column 50: syntax error while parsing value - invalid literal; last "
            "read: '1, N'");
        row("zero weight", smallDocument("\"weights\": [1, 1, 1, 1]", "\"weights\": [1, 1, 0, 1]"),
            "bad.json: surfaces[0].weights[2]: weights must be finite and > 0 (rational surfaces need positive "
            "weights)");
        row("wrong point count", smallDocument(", [1, 1, 0]]", "]"),
            "bad.json: surfaces[0].points: 3 entries, but countU·countV = 4; give exactly that many");
        row("wrong knot count", smallDocument("\"knotsU\": [0, 0, 1, 1]", "\"knotsU\": [0, 0, 1, 1, 1]"),
            "bad.json: surfaces[0].knotsU: 5 entries, but countU+degreeU+1 = 4; give exactly that many");
        row("degree too high", smallDocument("\"degreeU\": 1", "\"degreeU\": 9"),
            "bad.json: surfaces[0].degreeU: must be an integer in [1, 7], not 9");
        row("huge declared", smallDocument("\"countU\": 2, \"countV\": 2", "\"countU\": 1000000, \"countV\": 1000000"),
            "bad.json: surfaces[0].countV: countU·countV = 1000000000000 control points are more than the limit of "
            "1000000; split the surface");
        row("open seam", smallDocument("\"closedU\": false", "\"closedU\": true"),
            "bad.json: surfaces[0].points[1]: closedU is set, so control point (1, 0) must equal (0, 0) in position "
            "and weight; repeat the first column or clear closedU");
        row("unknown field", smallDocument("\"name\"", "\"nmae\""),
            "bad.json: surfaces[0].nmae: unknown field (known fields: name, degreeU, degreeV, countU, countV, closedU, "
            "closedV, knotsU, knotsV, points, weights)");
        row("missing field", smallDocument(",\n \"weights\": [1, 1, 1, 1]", ""),
            "bad.json: surfaces[0]: missing field 'weights'");
        row("wrong format", smallDocument("trimlab-nurbs", "trimlab-skeleton"),
            "bad.json: format: not a TrimLab NURBS file (\"format\" is not \"trimlab-nurbs\")");
        row("newer version", smallDocument("\"version\": 1", "\"version\": 2"),
            "bad.json: version: version 2 is newer than this TrimLab (1); update TrimLab to open it");
        row("no surfaces", R"({"format": "trimlab-nurbs", "version": 1, "surfaces": []})",
            "bad.json: surfaces: must hold 1 to 1024 surfaces, not 0");
        // Cut inside "countV" on line 2, whose 48 characters end there: column 49.
        row("truncated", smallDocument().substr(0, 120),
            "bad.json: truncated JSON at line 2, column 49: syntax error while parsing object key - invalid string: "
            "missing closing quote; last read: '\"count'; expected string literal");
    }

    void malformedJsonRefused()
    {
        QFETCH(QString, text);
        QFETCH(QString, message);
        QCOMPARE(loadError(text.toStdString()), message);
    }

    void missingFileNamed()
    {
        const std::filesystem::path path = test::outputDir() / "no such file.nurbs.json";
        try {
            (void)loadNurbsJson(path);
            QFAIL("loaded a missing file");
        } catch (const NurbsFileError& error) {
            QCOMPARE(QString::fromStdString(error.file()), QString::fromStdString(path.string()));
        }
    }

    void objExportReadsBack()
    {
        const NurbsTessellation t(makeNurbsCappedTube(kCenter, 1.0, 2.0), 12, 6);
        const std::string text = meshObjText(t.mesh(), t.normals(), "capped tube\nline two");
        QVERIFY(text.starts_with("# TrimLab\n# capped tube line two\nv "));
        QCOMPARE(std::count(text.begin(), text.end(), '\n'),
                 std::ptrdiff_t(2 + 2 * t.mesh().vertexCount() + t.mesh().triangleCount()));
        QVERIFY(text.find("\nvn ") != std::string::npos && text.find("//") != std::string::npos);
        const std::filesystem::path path = test::outputDir() / "capped_tube.obj";
        saveMeshObj(path, t.mesh(), t.normals());
        const TriangleMesh loaded = loadMesh(path);
        QCOMPARE(loaded, t.mesh());
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 (void)meshObjText(t.mesh(), std::vector<glm::vec3>(3, glm::vec3(0.0f))));
    }
};

QTEST_APPLESS_MAIN(TestNurbsTessellation)
#include "tst_nurbs_tessellation.moc"
