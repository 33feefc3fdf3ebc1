// `trimlab skeleton` as scripts call it: bad arguments exit 2 and refused meshes exit 1,
// each with one "trimlab: error: ..." line; a run prints the rig and the Table III row
// and writes a glTF that the Khronos validator accepts and a skeleton JSON that loads
// back with the same rig.
#include "gltf_validation.h"
#include "run_trimlab.h"

#include "core/scene/shape_generators.h"
#include "core/skeleton/skeleton_json.h"

#include <QDir>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <glm/vec2.hpp>

#include <cmath>
#include <fstream>
#include <vector>

using namespace trimlab;

using trimlab::test::Run;
using trimlab::test::runTrimlab;

namespace {

// A capsule around the y axis (radius 1, cylinder y ∈ [−3, 3]), about 1.3k vertices.
TriangleMesh capsule()
{
    std::vector<glm::dvec2> profile;
    for (int i = 0; i <= 8; ++i) {
        const double a = -M_PI / 2 + (M_PI / 2) * i / 8;
        profile.emplace_back(std::cos(a), -3.0 + std::sin(a));
    }
    for (int i = 1; i < 24; ++i)
        profile.emplace_back(1.0, -3.0 + 6.0 * i / 24);
    for (int i = 0; i <= 8; ++i) {
        const double a = (M_PI / 2) * i / 8;
        profile.emplace_back(std::cos(a), 3.0 + std::sin(a));
    }
    profile.front().x = 0.0;
    profile.back().x = 0.0;
    return makeSurfaceOfRevolution(profile, 32);
}

void writeObj(const TriangleMesh& mesh, const QString& path, std::size_t dropTriangles = 0)
{
    std::ofstream out(path.toStdString());
    for (const glm::vec3& p : mesh.positions)
        out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (std::size_t f = dropTriangles; f < mesh.triangleCount(); ++f)
        out << "f " << mesh.triangles[f].x + 1 << ' ' << mesh.triangles[f].y + 1 << ' ' << mesh.triangles[f].z + 1
            << '\n';
}

} // namespace

class TestSkeletonVerb : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void badArgumentsExitWithTwo_data();
    void badArgumentsExitWithTwo();
    void refusesAnOpenMesh();
    void refusesAMissingFile();
    void writesValidGlbAndJson();
    void loopSubdivisionRaisesTheVertexCount();
    void helpExitsWithZero();
    void fitsTheRigToAnAnimation();

private:
    QTemporaryDir m_dir;
    QString m_capsule;
};

void TestSkeletonVerb::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_capsule = m_dir.filePath("capsule.obj");
    writeObj(capsule(), m_capsule);
}

void TestSkeletonVerb::badArgumentsExitWithTwo_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    QTest::newRow("no mesh") << QStringList{"skeleton"} << "exactly one mesh";
    QTest::newRow("nodes") << QStringList{"skeleton", "x.obj", "--nodes", "many"} << "--nodes must be an integer";
    QTest::newRow("one node") << QStringList{"skeleton", "x.obj", "--nodes", "1"} << "from 2 to 10000";
    QTest::newRow("ordering") << QStringList{"skeleton", "x.obj", "--ordering", "rcm"} << "unknown --ordering 'rcm'";
    QTest::newRow("solver") << QStringList{"skeleton", "x.obj", "--solver", "qr"} << "unknown --solver 'qr'";
    QTest::newRow("root") << QStringList{"skeleton", "x.obj", "--nodes", "20", "--root", "20"} << "--root 20";
    QTest::newRow("levels") << QStringList{"skeleton", "x.obj", "--loop-subdivide", "9"} << "from 0 to 6";
    QTest::newRow("output") << QStringList{"skeleton", "x.obj", "-o", "rig.fbx"} << ".glb or .gltf";
    QTest::newRow("unknown") << QStringList{"skeleton", "x.obj", "--bones", "3"} << "Unknown option";
    QTest::newRow("rest pose of a mesh") << QStringList{"skeleton", "x.obj", "--rest-pose", "1"}
                                         << "--rest-pose needs an animation";
    QTest::newRow("subdivided animation")
        << QStringList{"skeleton", "pose_%d.obj", "--loop-subdivide", "1"} << "--loop-subdivide needs one mesh";
}

void TestSkeletonVerb::badArgumentsExitWithTwo()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    const Run run = runTrimlab(arguments);
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.startsWith("trimlab: error: ") && run.err.contains(message), qPrintable(run.err));
    QCOMPARE(run.err.count('\n'), 1);
}

void TestSkeletonVerb::refusesAnOpenMesh()
{
    const QString open = m_dir.filePath("open.obj");
    writeObj(capsule(), open, 1); // without its first triangle
    const QString glb = m_dir.filePath("open.glb");
    const Run run = runTrimlab({"skeleton", open, "-o", glb});
    QCOMPARE(run.exitCode, 1);
    QVERIFY2(run.err.startsWith("trimlab: error: ") && run.err.contains("open.obj") && run.err.contains("boundary"),
             qPrintable(run.err));
    QVERIFY(!QFile::exists(glb));
}

void TestSkeletonVerb::refusesAMissingFile()
{
    const Run run = runTrimlab({"skeleton", m_dir.filePath("missing.obj")});
    QCOMPARE(run.exitCode, 1);
    QVERIFY2(run.err.contains("missing.obj"), qPrintable(run.err));
}

void TestSkeletonVerb::writesValidGlbAndJson()
{
    const QString glb = m_dir.filePath("capsule.glb"), json = m_dir.filePath("capsule.json");
    const Run run = runTrimlab({"skeleton", m_capsule, "--nodes", "6", "-o", glb, "--json", json});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    for (const char* column : {"vertices", "iterations", "contraction", "simplification", "refinement", "selection",
                               "weights", "export", "total"})
        QVERIFY2(run.out.contains(column), qPrintable(run.out));
    // The row under the header starts with the vertex count.
    const QRegularExpression row(QStringLiteral(R"(\n\s+(\d+)\s+(\d+)\s+[0-9.]+\s+[0-9.]+)"));
    const QRegularExpressionMatch match = row.match(run.out);
    QVERIFY2(match.hasMatch(), qPrintable(run.out));
    QCOMPARE(match.captured(1).toULongLong(), qulonglong(capsule().vertexCount()));
    test::requireValidGltf(glb.toStdString());
    QVERIFY(!QTest::currentTestFailed());
    const SkeletonDocument document = loadSkeletonJson(json.toStdString());
    QVERIFY(document.rig.joints.size() >= 2);
    QCOMPARE(document.rig.bones.size() + 1, document.rig.joints.size());
    QCOMPARE(document.rig.vertexJoint.size(), capsule().vertexCount());
    QVERIFY(document.curve.has_value());
    QVERIFY2(run.out.contains(QStringLiteral("skeleton: %1 joints").arg(document.rig.joints.size())),
             qPrintable(run.out));
}

void TestSkeletonVerb::loopSubdivisionRaisesTheVertexCount()
{
    const QString glb = m_dir.filePath("capsule-loop.glb");
    const Run run = runTrimlab({"skeleton", m_capsule, "--nodes", "6", "--loop-subdivide", "1", "--ordering", "amd",
                                "--solver", "ldlt", "-o", glb});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    // V' = V + E = V + 3F/2 for a closed triangle mesh.
    const TriangleMesh c = capsule();
    const std::size_t subdivided = c.vertexCount() + 3 * c.triangleCount() / 2;
    QVERIFY2(run.out.contains(QStringLiteral("%1 vertices").arg(subdivided)), qPrintable(run.out));
    QVERIFY2(run.out.contains("Loop-subdivided 1x"), qPrintable(run.out));
    test::requireValidGltf(glb.toStdString());
}

void TestSkeletonVerb::helpExitsWithZero()
{
    const Run run = runTrimlab({"skeleton", "--help"});
    QCOMPARE(run.exitCode, 0);
    QVERIFY(run.out.contains("Usage: trimlab skeleton"));
    QVERIFY(run.out.contains("--loop-subdivide"));
    const Run usage = runTrimlab({"--help"});
    QVERIFY(usage.out.contains("trimlab skeleton MESH"));
}

// An animation folder: the rig is made from the rest pose (here the middle one) and
// fitted to every pose. The poses are the capsule turned and moved as a whole, which the
// rig reproduces exactly; a fit that did nothing would leave an error of the size of the
// motion.
void TestSkeletonVerb::fitsTheRigToAnAnimation()
{
    QDir(m_dir.path()).mkdir("capsule-motion");
    const TriangleMesh rest = capsule();
    for (int pose = 0; pose < 3; ++pose) {
        TriangleMesh moved = rest;
        const double angle = 0.3 * (pose - 1);
        for (glm::vec3& p : moved.positions)
            p = glm::vec3(std::cos(angle) * p.x - std::sin(angle) * p.y, std::sin(angle) * p.x + std::cos(angle) * p.y,
                          p.z + 0.5f * float(pose - 1));
        writeObj(moved, m_dir.filePath(QStringLiteral("capsule-motion/pose_%1.obj").arg(pose)));
    }
    const Run run = runTrimlab({"skeleton", m_dir.filePath("capsule-motion"), "--rest-pose", "1", "--nodes", "6"});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(run.out.contains("(the rest pose 1 of 3 poses)"), qPrintable(run.out));
    const QRegularExpression line(
        QStringLiteral(R"(rig   motion: E_RMS \S+ \(E_RMS/diagonal ([0-9.e+-]+)\) over 3 poses)"));
    const QRegularExpressionMatch match = line.match(run.out);
    QVERIFY2(match.hasMatch(), qPrintable(run.out));
    QVERIFY2(match.captured(1).toDouble() < 1e-3, qPrintable(run.out));
}

QTEST_GUILESS_MAIN(TestSkeletonVerb)
#include "tst_skeleton_verb.moc"
