#include "core/mesh/obj_reader.h"

#include "core/mesh/mesh_load_error.h"
#include "core/mesh/obj_line_parser.h"
#include "core/mesh/polygon_triangulation.h"
#include "core/mesh/reader_support.h"
#include "core/mesh/text_scanner.h"

namespace trimlab {

namespace {

// Parse state for one OBJ file. Faces are collected first and checked and triangulated at
// the end, because a face may name vertices defined after it.
class ObjParser : private ObjLineParser {
public:
    explicit ObjParser(const std::string& displayName) : ObjLineParser(displayName) {}

    void parseLine(std::string_view line, std::size_t lineNumber);
    TriangleMesh finish();

private:
    std::vector<glm::vec3> m_positions;
    PolygonSoup m_soup;
    std::vector<std::size_t> m_faceLines; // line of each polygon, for late range errors
};

void ObjParser::parseLine(std::string_view line, std::size_t lineNumber)
{
    setLine(lineNumber);
    std::string_view rest = stripComment(line);
    std::string_view keyword;
    if (!nextToken(rest, keyword))
        return;
    if (keyword == "v") {
        m_positions.emplace_back(parseVertexLine(rest, m_positions.size()));
    } else if (keyword == "f") {
        parseFaceLine(rest, m_positions.size(), m_soup.corners);
        m_soup.closePolygon();
        m_faceLines.push_back(this->line());
    }
    // vt, vn, vp, o, g, s, usemtl, mtllib, l, p and unknown keywords carry no geometry we use.
}

TriangleMesh ObjParser::finish()
{
    if (m_soup.polygonCount() == 0)
        throw MeshLoadError(name(), "the file contains no faces (" +
                                        countNoun(m_positions.size(), "vertex", "vertices") +
                                        ", but no 'f' lines); point clouds cannot be trimmed");
    for (std::size_t p = 0; p < m_soup.polygonCount(); ++p) {
        for (const std::uint32_t index : m_soup.polygon(p)) {
            if (index >= m_positions.size())
                throw MeshLoadError(name(),
                                    "face " + std::to_string(p + 1) + " references vertex " +
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
