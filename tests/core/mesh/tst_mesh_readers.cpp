// The format readers and their shared pieces, called directly on text and bytes made in
// the test: line and token scanning, byte cursors, the reader helpers, the OBJ line parser
// and the OBJ, OFF, PLY, STL and glTF readers, glTF accessors, vertex welding, corner
// angles, and the mesh writers read back by those readers.
#include "core/mesh/byte_cursor.h"
#include "core/mesh/corner_angle.h"
#include "core/mesh/gltf_accessor.h"
#include "core/mesh/gltf_reader.h"
#include "core/mesh/mesh_export.h"
#include "core/mesh/mesh_load_error.h"
#include "tests/core/mesh/mesh_error_text.h"
#include "core/mesh/obj_line_parser.h"
#include "core/mesh/obj_reader.h"
#include "core/mesh/off_reader.h"
#include "core/mesh/ply_header.h"
#include "core/mesh/ply_reader.h"
#include "core/mesh/ply_value_source.h"
#include "core/mesh/reader_support.h"
#include "core/mesh/stl_reader.h"
#include "core/mesh/text_scanner.h"
#include "core/mesh/vertex_welding.h"

#include "core/io/gltf_builder.h"

#include <QByteArray>
#include <QTemporaryDir>
#include <QtTest>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>

using namespace trimlab;

namespace {

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

// A unit right tetrahedron, outward faces.
TriangleMesh tetrahedron()
{
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return mesh;
}

std::string fileBytes(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

template <class T>
void appendBytes(std::string& bytes, T value)
{
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    bytes.append(raw, sizeof(T));
}

} // namespace

class TestMeshReaders : public QObject {
    Q_OBJECT

private slots:
    void linesEndInAnyTerminator()
    {
        LineScanner lines("a\r\nb\rc\n\nd");
        std::vector<std::string> seen;
        for (std::string_view line; lines.next(line);)
            seen.emplace_back(line);
        QCOMPARE(seen, (std::vector<std::string>{"a", "b", "c", "", "d"}));
        QCOMPARE(lines.lineNumber(), std::size_t(5));
        QCOMPARE(lines.bytesRemaining(), std::size_t(0));

        TokenStream tokens("1 2\n\n  three\t4", 10);
        std::string_view token;
        QVERIFY(tokens.next(token) && token == "1" && tokens.line() == 10);
        QVERIFY(tokens.next(token) && token == "2");
        QVERIFY(tokens.next(token) && token == "three" && tokens.line() == 12);
        QVERIFY(tokens.next(token) && token == "4");
        QVERIFY(!tokens.next(token));

        std::string_view rest = " v\t1  2 ";
        QVERIFY(nextToken(rest, token) && token == "v");
        QVERIFY(nextToken(rest, token) && token == "1");
        QVERIFY(nextToken(rest, token) && token == "2");
        QVERIFY(!nextToken(rest, token));
        QCOMPARE(withoutUtf8Bom("\xEF\xBB\xBFply"), std::string_view("ply"));
        QCOMPARE(withoutUtf8Bom("ply"), std::string_view("ply"));
        QCOMPARE(stripComment("v 1 2 3 # corner"), std::string_view("v 1 2 3 "));
    }

    void numbersParseWholeTokensOnly()
    {
        double d = 0.0;
        QVERIFY(parseDouble("-2.5e3", d) && d == -2500.0);
        QVERIFY(parseDouble("+4", d) && d == 4.0);
        QVERIFY(parseDouble("nan", d) && std::isnan(d));
        QVERIFY(parseDouble("inf", d) && std::isinf(d));
        QVERIFY(!parseDouble("1.5x", d));
        QVERIFY(!parseDouble("", d));
        std::int64_t i = 0;
        QVERIFY(parseInteger("-42", i) && i == -42);
        QVERIFY(parseInteger("+7", i) && i == 7);
        QVERIFY(!parseInteger("4.0", i));
        QVERIFY(!parseInteger("99999999999999999999", i));
    }

    void byteCursorsReadInTheirByteOrder()
    {
        const std::string data("\x01\x02\x03\x04\x05", 5);
        QCOMPARE(decodeScalar<std::uint16_t>(data.data(), std::endian::little), std::uint16_t(0x0201));
        QCOMPARE(decodeScalar<std::uint16_t>(data.data(), std::endian::big), std::uint16_t(0x0102));
        ByteCursor cursor(data, 1, std::endian::big);
        std::uint32_t word = 0;
        QVERIFY(cursor.read(word));
        QCOMPARE(word, 0x02030405u);
        QCOMPARE(cursor.remaining(), std::size_t(0));
        QVERIFY(!cursor.read(word));
        QCOMPARE(cursor.offset(), std::size_t(5));
        ByteCursor skipping(data, 0, std::endian::little);
        QVERIFY(skipping.skip(3));
        QVERIFY(!skipping.skip(3)); // nothing consumed
        QCOMPARE(skipping.rest(), std::string_view("\x04\x05", 2));
        QCOMPARE(ByteCursor(data, 99, std::endian::little).remaining(), std::size_t(0));
    }

    void readerHelpersWordTheirMessages()
    {
        QCOMPARE(cappedReserve(1'000'000'000, 100, 10), std::size_t(11));
        QCOMPARE(cappedReserve(3, 100, 10), std::size_t(3));
        QVERIFY(isFiniteFloat(3.0e38) && !isFiniteFloat(1e39) && !isFiniteFloat(std::nan("")));
        QCOMPARE(describeNonFinite(-std::numeric_limits<double>::infinity()), std::string("-inf"));
        QCOMPARE(describeNonFinite(1e300), std::string("1e+300 (too large for a 32-bit float)"));
        QCOMPARE(nonFiniteCoordinateReason(std::nan("")),
                 std::string("has a non-finite coordinate (nan); coordinates must be finite numbers"));
        QCOMPARE(vertexCountPhrase(8, true), std::string("the file has only 8 vertices (numbered 0 to 7)"));
        QCOMPARE(vertexCountPhrase(1, false), std::string("the file has only 1 vertex"));
        QCOMPARE(vertexCountPhrase(0, true), std::string("the file has no vertices"));
        QCOMPARE(countNoun(2, "face", "faces"), std::string("2 faces"));
        QVERIFY(test::meshLoadError([] { rejectBinaryData("text", "a.obj", "OBJ"); }).empty());
        QCOMPARE(test::meshLoadError([] { rejectBinaryData(std::string_view("ab\0c", 4), "a.obj", "OBJ"); }),
                 std::string("a.obj: binary data in a text format (a NUL byte at byte offset 2); is this really an "
                             "OBJ file?"));
    }

    void objLinesParseVerticesAndCorners()
    {
        const std::string name = "a.obj";
        ObjLineParser parser(name);
        parser.setLine(12);
        QCOMPARE(parser.parseVertexLine(" 1 2.5 -3 1", 0), glm::dvec3(1, 2.5, -3));
        std::vector<std::uint32_t> corners;
        QCOMPARE(parser.parseFaceLine("1 2/5 3//7 -1/2/3", 4, corners), std::uint32_t(4));
        QCOMPARE(corners, (std::vector<std::uint32_t>{0, 1, 2, 3}));
        QVERIFY(contains(test::meshLoadError([&] { (void)parser.parseVertexLine("1 2", 0); }), "a.obj:12: "));
        QVERIFY(!test::meshLoadError([&] { (void)parser.parseVertexLine("1 x 2", 0); }).empty());
        QVERIFY(!test::meshLoadError([&] { (void)parser.parseVertexLine("1 1e39 2", 0); }).empty());
        QVERIFY(!test::meshLoadError([&] { (void)parser.parseFaceLine("0 1 2", 3, corners); }).empty());
        QVERIFY(!test::meshLoadError([&] { (void)parser.parseFaceLine("1 2", 3, corners); }).empty());
        QVERIFY(!test::meshLoadError([&] { (void)parser.parseFaceLine("-4 1 2", 3, corners); }).empty());
        QVERIFY(!test::meshLoadError([&] { (void)parser.parseFaceLine("1 2/ /3 3", 3, corners); }).empty());
        corners.clear();
        QCOMPARE(parser.parseFaceLine("1 2 9", 3, corners), std::uint32_t(3)); // forward: the caller checks
        QCOMPARE(corners.back(), std::uint32_t(8));
    }

    void objAndOffTextsLoad()
    {
        const TriangleMesh quad =
            readObj("\xEF\xBB\xBF# a quad\nvt 0 0\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 -1\n", "q.obj");
        QCOMPARE(quad.vertexCount(), std::size_t(4));
        QCOMPARE(quad.triangleCount(), std::size_t(2));
        QVERIFY(contains(test::meshLoadError([] { (void)readObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 5\n", "b.obj"); }),
                         "b.obj:4: face 1 references vertex 5, but the file has only 3 vertices"));
        QVERIFY(contains(test::meshLoadError([] { (void)readObj("v 0 0 0\n", "b.obj"); }), "contains no faces"));

        const TriangleMesh off = readOff("OFF\n# comment\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n", "q.off");
        QCOMPARE(off.vertexCount(), std::size_t(4));
        QCOMPARE(off.triangleCount(), std::size_t(2));
        QVERIFY(contains(test::meshLoadError([] { (void)readOff("OFF\n8 1 0\n0 0 0\n1 0 0\n", "t.off"); }),
                         "declares 8 vertices"));
        QVERIFY(
            contains(test::meshLoadError([] { (void)readOff("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "t.off"); }),
                     "face 0"));
    }

    void plyHeadersDescribeTheirElements()
    {
        const std::string text = "ply\nformat binary_big_endian 1.0\ncomment made here\nelement vertex 2\n"
                                 "property float x\nproperty uchar red\nelement face 1\n"
                                 "property list uint8 int vertex_indices\nend_header\n";
        const PlyHeader header = parsePlyHeader(text + "rest", "h.ply");
        QCOMPARE(header.encoding, PlyEncoding::BinaryBigEndian);
        QCOMPARE(header.elements.size(), std::size_t(2));
        QCOMPARE(header.elements[0].count, std::uint64_t(2));
        QCOMPARE(header.elements[0].findProperty("red"), 1);
        QCOMPARE(header.elements[0].findProperty("y"), -1);
        QCOMPARE(header.elements[0].fixedBinarySize(), std::size_t(5));
        QVERIFY(header.elements[1].properties[0].isList);
        QCOMPARE(header.elements[1].properties[0].countType, PlyScalarType::UInt8);
        QCOMPARE(header.elements[1].fixedBinarySize(), std::size_t(0));
        QCOMPARE(header.elements[1].headerLine, std::size_t(7));
        QCOMPARE(header.dataOffset, text.size());
        QCOMPARE(plyScalarSize(PlyScalarType::Float64), std::size_t(8));
        QVERIFY(isPlyIntegerType(PlyScalarType::UInt16) && !isPlyIntegerType(PlyScalarType::Float32));
        QVERIFY(!test::meshLoadError([] { (void)parsePlyHeader("plx\n", "h.ply"); }).empty());
        QVERIFY(contains(test::meshLoadError([] {
                             (void)parsePlyHeader("ply\nformat ascii 1.0\nelement v 1\nproperty half x\n"
                                                  "end_header\n",
                                                  "h.ply");
                         }),
                         "h.ply:4"));
        QVERIFY(!test::meshLoadError([] {
                     (void)parsePlyHeader("ply\nformat ascii 1.0\nelement v 1\n", "h.ply");
                 }).empty());
    }

    void plyValuesReadTokensOrBytes()
    {
        const std::string ascii = "ply\nformat ascii 1.0\nelement v 2\nproperty int a\nproperty float b\nend_header\n"
                                  "7 2.5\n1.5 x\n";
        const PlyHeader header = parsePlyHeader(ascii, "a.ply");
        PlyValueSource values(ascii, header);
        double v = 0.0;
        QCOMPARE(values.read(PlyScalarType::Int32, v), PlyValueSource::Status::Ok);
        QCOMPARE(v, 7.0);
        QCOMPARE(values.read(PlyScalarType::Float32, v), PlyValueSource::Status::Ok);
        QCOMPARE(v, 2.5);
        QCOMPARE(values.line(), std::size_t(7));
        QCOMPARE(values.read(PlyScalarType::Int32, v), PlyValueSource::Status::Malformed); // 1.5 is no int
        QCOMPARE(values.lastToken(), std::string_view("1.5"));
        QCOMPARE(values.read(PlyScalarType::Float32, v), PlyValueSource::Status::Malformed);
        QCOMPARE(values.read(PlyScalarType::Float32, v), PlyValueSource::Status::End);

        std::string binary = "ply\nformat binary_little_endian 1.0\nelement v 1\nproperty short a\nend_header\n";
        const std::size_t body = binary.size();
        appendBytes(binary, std::int16_t(-3));
        binary += "xyz";
        const PlyHeader binaryHeader = parsePlyHeader(binary, "b.ply");
        PlyValueSource bytes(binary, binaryHeader);
        QVERIFY(bytes.couldHold(1, PlyScalarType::Int16) && !bytes.couldHold(4, PlyScalarType::Int16));
        QCOMPARE(bytes.read(PlyScalarType::Int16, v), PlyValueSource::Status::Ok);
        QCOMPARE(v, -3.0);
        QCOMPARE(bytes.position(), "byte offset " + std::to_string(body));
        QCOMPARE(bytes.bytesRemaining(), std::size_t(3));
        QCOMPARE(bytes.trailingData(), std::string("3 bytes"));
        QCOMPARE(bytes.read(PlyScalarType::Int32, v), PlyValueSource::Status::End);
    }

    void plyAndStlFilesLoad()
    {
        const std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                "property float z\nproperty uchar red\nelement face 1\n"
                                "property list uchar int vertex_indices\nend_header\n"
                                "0 0 0 9\n1 0 0 9\n0 1 0 9\n3 0 1 2\n";
        const TriangleMesh triangle = readPly(ply, "t.ply");
        QCOMPARE(triangle.positions, (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
        QCOMPARE(triangle.triangles, (std::vector<glm::uvec3>{{0, 1, 2}}));
        std::string bad = ply;
        bad.replace(bad.rfind("3 0 1 2"), 7, "3 0 1 5");
        QVERIFY(contains(test::meshLoadError([&] { (void)readPly(bad, "t.ply"); }), "face 0"));

        // Binary STL: two facets sharing an edge, welded into four vertices.
        std::string stl(80, ' ');
        stl.replace(0, 5, "solid"); // binary despite the "solid" header: the size says so
        appendBytes(stl, std::uint32_t(2));
        const float facets[2][9] = {{0, 0, 0, 1, 0, 0, 1, 1, 0}, {0, 0, 0, 1, 1, 0, 0, 1, 0}};
        for (const auto& facet : facets) {
            for (int k = 0; k < 3; ++k)
                appendBytes(stl, 0.0f); // normal: ignored
            for (float c : facet)
                appendBytes(stl, c);
            appendBytes(stl, std::uint16_t(0));
        }
        const TriangleMesh welded = readStl(stl, "q.stl");
        QCOMPARE(welded.vertexCount(), std::size_t(4));
        QCOMPARE(welded.triangles, (std::vector<glm::uvec3>{{0, 1, 2}, {0, 2, 3}}));
        QVERIFY(!test::meshLoadError([&] { (void)readStl(stl.substr(0, 100), "q.stl"); }).empty());
        const TriangleMesh ascii = readStl("solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                                           "vertex 0 1 0\nendloop\nendfacet\nendsolid t\n",
                                           "t.stl");
        QCOMPARE(ascii.triangleCount(), std::size_t(1));
    }

    void weldingMergesIdenticalPositionsOnly()
    {
        TriangleMesh mesh;
        mesh.positions = {{0, 0, 0}, {1, 0, 0}, {-0.0f, 0, 0}, {1, 0, 0}, {1, 1e-7f, 0}};
        mesh.triangles = {{0, 1, 4}, {2, 3, 4}};
        const TriangleMesh welded = weldIdenticalVertices(mesh);
        QCOMPARE(welded.positions, (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {1, 1e-7f, 0}}));
        QCOMPARE(welded.triangles, (std::vector<glm::uvec3>{{0, 1, 2}, {0, 1, 2}}));
    }

    void cornerAnglesAreInteriorAngles()
    {
        const glm::dvec3 o(0.0), x(1, 0, 0), y(0, 2, 0);
        QVERIFY(std::abs(cornerAngle(o, x, y) - glm::half_pi<double>()) < 1e-15);
        QVERIFY(std::abs(cornerAngle(o, x, glm::dvec3(1, 1, 0)) - glm::quarter_pi<double>()) < 1e-15);
        QVERIFY(std::abs(cornerAngle(o, x, -x) - glm::pi<double>()) < 1e-15);
        QCOMPARE(cornerAngle(o, o, y), 0.0);
    }

    // Accessors read positions, numbers and indices from a model made by the glTF builder;
    // bad references and out-of-range indices name the accessor.
    void gltfAccessorsReadWhatTheBuilderWrote()
    {
        tinygltf::Model model;
        model.buffers.emplace_back();
        const std::vector<glm::vec3> positions = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
        const int p = io::addGltfVec3Accessor(model, positions, TINYGLTF_TARGET_ARRAY_BUFFER, true);
        const int i = io::addGltfTriangleIndices(model, {{0, 1, 2}});
        const int s = io::addGltfFloatAccessor(model, {0.5f, 1.5f}, TINYGLTF_TYPE_SCALAR, true);
        const std::string name = "m.gltf";
        const GltfReadContext context{name, "mesh 0 primitive 0"};
        QCOMPARE(readGltfPositions(model, p, context), positions);
        QCOMPARE(readGltfIndices(model, i, 3, context), (std::vector<std::uint32_t>{0, 1, 2}));
        QCOMPARE(readGltfNumbers(model, s, TINYGLTF_TYPE_SCALAR, context), (std::vector<double>{0.5, 1.5}));
        QVERIFY(contains(test::meshLoadError([&] { (void)readGltfIndices(model, i, 2, context); }), "m.gltf"));
        QVERIFY(!test::meshLoadError([&] { (void)readGltfPositions(model, 99, context); }).empty());
        QVERIFY(!test::meshLoadError([&] { (void)readGltfPositions(model, s, context); }).empty()); // a SCALAR
        QVERIFY(!test::meshLoadError([&] { (void)readGltfNumbers(model, p, TINYGLTF_TYPE_SCALAR, context); }).empty());
    }

    // A glTF with its buffer in a data URI: read from memory, with the node's translation.
    void gltfTextsLoadInSceneSpace()
    {
        const float data[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        const QByteArray base64 = QByteArray(reinterpret_cast<const char*>(data), sizeof(data)).toBase64();
        const std::string gltf =
            "{\"asset\": {\"version\": \"2.0\"}, \"scene\": 0, \"scenes\": [{\"nodes\": [0]}],"
            " \"nodes\": [{\"mesh\": 0, \"translation\": [0, 0, 5]}],"
            " \"meshes\": [{\"primitives\": [{\"attributes\": {\"POSITION\": 0}}]}],"
            " \"accessors\": [{\"bufferView\": 0, \"componentType\": 5126, \"count\": 3, \"type\": \"VEC3\","
            " \"min\": [0, 0, 0], \"max\": [1, 1, 0]}],"
            " \"bufferViews\": [{\"buffer\": 0, \"byteLength\": 36}],"
            " \"buffers\": [{\"byteLength\": 36, \"uri\": \"data:application/octet-stream;base64," +
            base64.toStdString() + "\"}]}";
        const TriangleMesh mesh = readGltf(gltf, "t.gltf", {});
        QCOMPARE(mesh.positions, (std::vector<glm::vec3>{{0, 0, 5}, {1, 0, 5}, {0, 1, 5}}));
        QCOMPARE(mesh.triangles, (std::vector<glm::uvec3>{{0, 1, 2}}));
        QVERIFY(contains(test::meshLoadError([&] { (void)readGltf(gltf.substr(0, 40), "t.gltf", {}); }), "t.gltf"));
    }

    // Every export format reads back as the same mesh.
    void exportsReadBackAsWritten()
    {
        QVERIFY(isMeshExportPath("a.OBJ") && isMeshExportPath("b.glb") && !isMeshExportPath("c.off"));
        QCOMPARE(meshExportFormatsText(), std::string("obj, ply, stl, gltf or glb"));
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::filesystem::path root = dir.path().toStdString();
        const TriangleMesh mesh = tetrahedron();
        const auto readBack = [&](const std::string& extension) -> TriangleMesh {
            const std::filesystem::path path = root / ("t." + extension);
            saveTriangleMesh(path, mesh, "tst_mesh_readers");
            const std::string bytes = fileBytes(path);
            if (extension == "obj")
                return readObj(bytes, path.string());
            if (extension == "ply")
                return readPly(bytes, path.string());
            if (extension == "stl")
                return readStl(bytes, path.string());
            return readGltf(bytes, path.string(), root);
        };
        for (const std::string extension : {"obj", "ply", "gltf", "glb"}) {
            const TriangleMesh back = readBack(extension);
            QVERIFY2(back == mesh, extension.c_str());
        }
        // STL stores corners, not vertices: the welded vertices come in order of first use.
        const TriangleMesh stl = readBack("stl");
        QCOMPARE(stl.vertexCount(), mesh.vertexCount());
        QCOMPARE(stl.triangleCount(), mesh.triangleCount());
        for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
            for (int k = 0; k < 3; ++k)
                QCOMPARE(stl.positions[stl.triangles[t][k]], mesh.positions[mesh.triangles[t][k]]);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, saveTriangleMesh(root / "t.off", mesh));
        TriangleMesh broken = mesh;
        broken.triangles[0][1] = 4;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, saveTriangleMesh(root / "b.obj", broken));
        QVERIFY_THROWS_EXCEPTION(std::runtime_error, saveTriangleMesh(root / "missing" / "t.obj", mesh));
    }

    // No writer hands a non-finite coordinate to the next tool: each format refuses the
    // mesh naming the file and the vertex, and writes nothing.
    void writersRefuseNonFiniteVertices()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::filesystem::path root = dir.path().toStdString();
        TriangleMesh overflowed = tetrahedron();
        overflowed.positions[2].y = std::numeric_limits<float>::infinity();
        for (const std::string extension : {"obj", "ply", "stl", "gltf", "glb"}) {
            const std::filesystem::path path = root / ("inf." + extension);
            std::string message;
            try {
                saveTriangleMesh(path, overflowed);
            } catch (const std::invalid_argument& e) {
                message = e.what();
            }
            QVERIFY2(contains(message, path.string() + ": vertex 2 has a non-finite coordinate (inf)"),
                     (extension + ": " + message).c_str());
            QVERIFY(!std::filesystem::exists(path));
        }
        // The glTF builder behind the animation exports refuses the same.
        tinygltf::Model model;
        model.buffers.emplace_back();
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, io::addGltfVec3Accessor(model, overflowed.positions, 0, true));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 io::addGltfFloatAccessor(model, {0.0f, std::nanf("")}, TINYGLTF_TYPE_SCALAR, true));
    }
};

QTEST_GUILESS_MAIN(TestMeshReaders)
#include "tst_mesh_readers.moc"
