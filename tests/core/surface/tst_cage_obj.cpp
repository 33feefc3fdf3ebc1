// The cage OBJ reader (core/surface/cage_obj.h): polygons kept with their corner counts,
// OpenSubdiv shape-file crease and corner tags, gzip input, and malformed cages reported
// with file, line and reason.
#include "core/surface/cage_obj.h"

#include "core/mesh/mesh_load_error.h"

#include <QtTest>

#include <zlib.h>

#include <fstream>

using namespace trimlab;

namespace {

// A pentagonal prism: two pentagons and five quads, with every corner form OBJ allows.
const char* const kPrism = R"(# a prism cage
v 1 0 -1
v 0.309 0.951 -1
v -0.809 0.588 -1
v -0.809 -0.588 -1
v 0.309 -0.951 -1
v 1 0 1
v 0.309 0.951 1
v -0.809 0.588 1
v -0.809 -0.588 1
v 0.309 -0.951 1
vt 0 0
vn 0 0 1
f 5 4 3 2 1
f 6/1 7/1 8/1 9/1 10/1   # v/vt
f 1//1 2//1 7//1 6//1
f 2/1/1 3/1/1 8/1/1 7/1/1
f -8 -7 -2 -3
f 4 5 10 9
f 5 1 6 10
t crease 2/1/0 0 1 10
t crease 4/2/0 5 6 6 7 1.5 2.5
t corner 1/1/0 9 3
)";

SubdivisionCage read(const std::string& text, SubdivisionScheme scheme = SubdivisionScheme::CatmullClark)
{
    return readCageObj(text, "cage.obj", scheme);
}

// A unit square's four vertices, then `faces` (line 5 onwards).
std::string square(const std::string& faces)
{
    return "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n" + faces;
}

} // namespace

class TestCageObj : public QObject {
    Q_OBJECT

private slots:
    void keepsPolygonsAndTags();
    void readsGzipFiles();
    void malformedCages_data();
    void malformedCages();
};

void TestCageObj::keepsPolygonsAndTags()
{
    const SubdivisionCage cage = read(kPrism);
    QCOMPARE(cage.vertexCount(), std::size_t(10));
    QCOMPARE(cage.faceSizes, (std::vector<std::uint32_t>{5, 5, 4, 4, 4, 4, 4}));
    QCOMPARE(cage.faceIndices.size(), std::size_t(30));
    QCOMPARE(std::vector<std::uint32_t>(cage.face(1).begin(), cage.face(1).end()),
             (std::vector<std::uint32_t>{5, 6, 7, 8, 9}));
    // -8 -7 -2 -3 counted back from the 10th vertex: 3 4 9 8 (1-based) = 2 3 8 7.
    QCOMPARE(std::vector<std::uint32_t>(cage.face(4).begin(), cage.face(4).end()),
             (std::vector<std::uint32_t>{2, 3, 8, 7}));
    QCOMPARE(cage.positions[1], glm::dvec3(0.309, 0.951, -1));
    QCOMPARE(cage.creases.size(), std::size_t(3));
    QCOMPARE(cage.creases[0].a, 0u);
    QCOMPARE(cage.creases[0].b, 1u);
    QCOMPARE(cage.creases[0].sharpness, 10.0f);
    QCOMPARE(cage.creases[2].a, 6u);
    QCOMPARE(cage.creases[2].b, 7u);
    QCOMPARE(cage.creases[2].sharpness, 2.5f);
    QCOMPARE(cage.corners.size(), std::size_t(1));
    QCOMPARE(cage.corners[0].vertex, 9u);
    QCOMPARE(cage.corners[0].sharpness, 3.0f);
    QCOMPARE(cage.scheme, SubdivisionScheme::CatmullClark);
}

void TestCageObj::readsGzipFiles()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string path = dir.filePath("prism.obj.gz").toStdString();
    gzFile out = gzopen(path.c_str(), "wb");
    QVERIFY(out != nullptr);
    QVERIFY(gzputs(out, kPrism) > 0);
    QCOMPARE(gzclose(out), Z_OK);
    const SubdivisionCage cage = loadCageObj(path);
    QCOMPARE(cage.faceCount(), std::size_t(7));
    QCOMPARE(cage.creases.size(), std::size_t(3));
    try {
        (void)loadCageObj(dir.filePath("missing.obj").toStdString());
        QFAIL("a missing file was read");
    } catch (const MeshLoadError& e) {
        QCOMPARE(QString::fromStdString(e.reason()), QString("cannot open the file: it does not exist"));
    }
}

void TestCageObj::malformedCages_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("scheme");
    QTest::addColumn<QString>("message");
    const int cc = int(SubdivisionScheme::CatmullClark);
    QTest::newRow("two corners") << QString::fromStdString(square("f 1 2 3 4\nf 1 2\n")) << cc
                                 << "cage.obj:6: the face has 2 vertices; a face needs at least 3";
    QTest::newRow("index out of range") << QString::fromStdString(square("# ok\nf 1 2 3 9\n")) << cc
                                        << "cage.obj:6: face 1 references vertex 9, but the file has only 4 vertices";
    QTest::newRow("repeated corner") << QString::fromStdString(square("f 1 2 3 4\nf 1 2 2\n")) << cc
                                     << "cage.obj:6: cage face 1 repeats vertex 1; remove the repeated corner";
    QTest::newRow("non-manifold edge")
        << QString("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n") << cc
        << "cage.obj:8: cage edge 0-1 is used by 3 faces (non-manifold; first faces 0, 1, 2); each edge may "
           "border at most two faces";
    QTest::newRow("inconsistent orientation")
        << QString::fromStdString(square("f 1 2 3\nf 1 3 4\nf 1 2 4\n")) << cc
        << "cage.obj:7: cage edge 0-1 runs the same way in faces 0 and 2 (inconsistent orientation); reverse one "
           "of them so neighbours agree";
    QTest::newRow("quad under Loop") << QString::fromStdString(square("f 1 2 3\nf 1 3 4\nf 4 3 2 1\n"))
                                     << int(SubdivisionScheme::Loop)
                                     << "cage.obj:7: Loop subdivision needs triangles, but cage face 2 has 4 corners; "
                                        "triangulate the cage or use Catmull-Clark";
    QTest::newRow("crease on a diagonal") << QString::fromStdString(square("f 1 2 3 4\nt crease 2/1/0 0 2 10\n")) << cc
                                          << "cage.obj:6: crease 0 (0-2) is not an edge of the cage; a crease must "
                                             "join two corners that follow each other in a face";
    QTest::newRow("crease vertex out of range")
        << QString::fromStdString(square("f 1 2 3 4\nt crease 2/1/0 3 4 10\n")) << cc
        << "cage.obj:6: crease 0 (3-4) names a vertex >= 4, the cage's vertex count";
    QTest::newRow("unknown tag") << QString::fromStdString(square("f 1 2 3 4\nt hole 1/0/0 0\n")) << cc
                                 << "cage.obj:6: unsupported tag 'hole'; cages support 't crease' and 't corner'";
    QTest::newRow("short tag")
        << QString::fromStdString(square("f 1 2 3 4\nt corner 2/1/0 1\n")) << cc
        << "cage.obj:6: tag 'corner' declares 2 integers and 1 numbers, but the line ends after 1";
    QTest::newRow("negative sharpness") << QString::fromStdString(square("f 1 2 3 4\nt corner 1/1/0 1 -2\n")) << cc
                                        << "cage.obj:6: sharpness -2 is invalid; use a number >= 0 (10 or more is "
                                           "infinitely sharp)";
    QTest::newRow("two coordinates") << QString("v 0 0\n") << cc
                                     << "cage.obj:1: a vertex needs 3 coordinates (v x y z), but this line has 2";
    QTest::newRow("unused vertex") << QString::fromStdString(square("v 5 5 5\nf 1 2 3 4\n")) << cc
                                   << "cage.obj: cage vertex 4 is used by no face; remove unused vertices";
    QTest::newRow("no faces") << QString::fromStdString(square("")) << cc
                              << "cage.obj: the file contains no faces (4 vertices, but no 'f' lines); a cage needs "
                                 "polygons";
}

void TestCageObj::malformedCages()
{
    QFETCH(QString, text);
    QFETCH(int, scheme);
    QFETCH(QString, message);
    try {
        (void)read(text.toStdString(), SubdivisionScheme(scheme));
        QFAIL("a malformed cage was accepted");
    } catch (const MeshLoadError& e) {
        QCOMPARE(QString(e.what()), message);
    }
}

QTEST_GUILESS_MAIN(TestCageObj)
#include "tst_cage_obj.moc"
