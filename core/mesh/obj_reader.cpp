#include "mesh/obj_reader.h"

#include "mesh/mesh_load_error.h"
#include "mesh/polygon_triangulation.h"
#include "mesh/reader_support.h"
#include "mesh/text_scanner.h"

namespace trimlab {

namespace {

// Parse state for one OBJ file. Faces are collected first and checked and triangulated at
// the end, because a face may name vertices defined after it.
class ObjParser {
public:
    explicit ObjParser(const std::string& displayName) : m_name(displayName) {}

    void parseLine(std::string_view line, std::size_t lineNumber);
    TriangleMesh finish();

private:
    [[noreturn]] void fail(const std::string& reason) const
    {
        throw MeshLoadError(m_name, reason, {.line = m_line, .element = {}});
    }
    void parseVertex(std::string_view rest);
    void parseFace(std::string_view rest);
    std::uint32_t parseCorner(std::string_view corner);

    const std::string& m_name;
    std::size_t m_line = 0;
    std::vector<glm::vec3> m_positions;
    PolygonSoup m_soup;
    std::vector<std::size_t> m_faceLines; // line of each polygon, for late range errors
};

void ObjParser::parseLine(std::string_view line, std::size_t lineNumber)
{
    m_line = lineNumber;
    std::string_view rest = stripComment(line);
    std::string_view keyword;
    if (!nextToken(rest, keyword))
        return;
    if (keyword == "v")
        parseVertex(rest);
    else if (keyword == "f")
        parseFace(rest);
    // vt, vn, vp, o, g, s, usemtl, mtllib, l, p and unknown keywords carry no geometry we use.
}

void ObjParser::parseVertex(std::string_view rest)
{
    double xyz[3];
    for (int c = 0; c < 3; ++c) {
        std::string_view token;
        if (!nextToken(rest, token))
            fail("a vertex needs 3 coordinates (v x y z), but this line has " + std::to_string(c));
        if (!parseDouble(token, xyz[c]))
            fail("'" + std::string(token) + "' is not a number");
        if (!isFiniteFloat(xyz[c]))
            fail("vertex " + std::to_string(m_positions.size() + 1) + ' ' + nonFiniteCoordinateReason(xyz[c]));
    }
    if (m_positions.size() >= kMaxMeshVertices)
        fail("too many vertices; at most 4294967295 are supported");
    m_positions.emplace_back(static_cast<float>(xyz[0]), static_cast<float>(xyz[1]), static_cast<float>(xyz[2]));
}

std::uint32_t ObjParser::parseCorner(std::string_view corner)
{
    const std::string_view vertexPart = corner.substr(0, corner.find('/'));
    std::int64_t index = 0;
    if (!parseInteger(vertexPart, index))
        fail("'" + std::string(corner) + "' is not a valid face corner (expected v, v/vt, v//vn or v/vt/vn)");
    const auto defined = static_cast<std::int64_t>(m_positions.size());
    if (index == 0)
        fail("vertex index 0 is invalid: OBJ indices count from 1 (or back from -1)");
    if (index < 0) {
        if (-index > defined)
            fail("face references vertex " + std::to_string(index) + " (counting back), but only " +
                 countNoun(static_cast<std::uint64_t>(defined), "vertex is", "vertices are") +
                 " defined before this line");
        return static_cast<std::uint32_t>(defined + index);
    }
    if (static_cast<std::uint64_t>(index) > kMaxMeshVertices)
        fail("face references vertex " + std::to_string(index) + ", far beyond the supported vertex count");
    return static_cast<std::uint32_t>(index - 1);
}

void ObjParser::parseFace(std::string_view rest)
{
    std::string_view token;
    std::size_t count = 0;
    while (nextToken(rest, token)) {
        m_soup.corners.push_back(parseCorner(token));
        ++count;
    }
    if (count < 3)
        fail("the face has " + countNoun(count, "vertex", "vertices") + "; a face needs at least 3");
    m_soup.closePolygon();
    m_faceLines.push_back(m_line);
}

TriangleMesh ObjParser::finish()
{
    if (m_soup.polygonCount() == 0)
        throw MeshLoadError(m_name, "the file contains no faces (" +
                                        countNoun(m_positions.size(), "vertex", "vertices") +
                                        ", but no 'f' lines); point clouds cannot be trimmed");
    for (std::size_t p = 0; p < m_soup.polygonCount(); ++p) {
        for (const std::uint32_t index : m_soup.polygon(p)) {
            if (index >= m_positions.size())
                throw MeshLoadError(m_name, "face " + std::to_string(p + 1) + " references vertex " +
                                                std::to_string(std::uint64_t(index) + 1) + ", but " +
                                                vertexCountPhrase(m_positions.size(), false),
                                    {.line = m_faceLines[p], .element = {}});
        }
    }
    TriangleMesh mesh;
    mesh.triangles = triangulatePolygons(m_positions, m_soup);
    mesh.positions = std::move(m_positions);
    return mesh;
}

} // namespace

TriangleMesh readObj(std::string_view text, const std::string& displayName)
{
    rejectBinaryData(text, displayName, "OBJ");
    ObjParser parser(displayName);
    LineScanner lines(withoutUtf8Bom(text));
    std::string_view line;
    while (lines.next(line))
        parser.parseLine(line, lines.lineNumber());
    return parser.finish();
}

} // namespace trimlab
