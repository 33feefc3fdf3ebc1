#include "core/mesh/off_reader.h"

#include "core/mesh/mesh_load_error.h"
#include "core/mesh/polygon_triangulation.h"
#include "core/mesh/reader_support.h"
#include "core/mesh/text_scanner.h"

namespace trimlab {

namespace {

// True for the OFF header keywords [ST][C][N][4][n]OFF that describe 3D data. Sets
// `unsupported` for the 4D and nD variants.
bool isOffKeyword(std::string_view word, bool& unsupported)
{
    if (word.size() < 3 || word.substr(word.size() - 3) != "OFF")
        return false;
    std::string_view prefix = word.substr(0, word.size() - 3);
    unsupported = false;
    for (const std::string_view part : {"ST", "C", "N", "4", "n"}) {
        if (prefix.substr(0, part.size()) == part) {
            unsupported = unsupported || part == "4" || part == "n";
            prefix.remove_prefix(part.size());
        }
    }
    return prefix.empty();
}

class OffParser {
public:
    OffParser(std::string_view text, const std::string& displayName) : m_lines(text), m_name(displayName) {}

    TriangleMesh parse();

private:
    [[noreturn]] void fail(const std::string& reason, std::string element = {}) const
    {
        throw MeshLoadError(m_name, reason, {.line = m_lines.lineNumber(), .element = std::move(element)});
    }
    bool nextDataLine(std::string_view& line);
    void parseHeader();
    std::uint64_t parseCount(std::string_view token, const char* what);
    void parseVertex(std::size_t v);
    void parseFace(std::size_t f);
    std::uint32_t parseIndex(std::string_view token, std::size_t f, std::size_t corner, std::size_t declared);

    LineScanner m_lines;
    const std::string& m_name;
    std::uint64_t m_vertexCount = 0;
    std::uint64_t m_faceCount = 0;
    std::vector<glm::vec3> m_positions;
    PolygonSoup m_soup;
};

// The next line that is not blank after removing its comment.
bool OffParser::nextDataLine(std::string_view& line)
{
    while (m_lines.next(line)) {
        line = stripComment(line);
        std::string_view probe = line;
        std::string_view token;
        if (nextToken(probe, token))
            return true;
    }
    return false;
}

std::uint64_t OffParser::parseCount(std::string_view token, const char* what)
{
    std::int64_t count = 0;
    if (!parseInteger(token, count) || count < 0)
        fail(std::string("invalid ") + what + " count '" + std::string(token) + "' in the OFF header");
    if (static_cast<std::uint64_t>(count) > kMaxMeshVertices)
        fail(std::string("the header declares ") + std::to_string(count) + ' ' + what +
             "s; at most 4294967295 are supported");
    return static_cast<std::uint64_t>(count);
}

void OffParser::parseHeader()
{
    std::string_view line;
    std::string_view keyword;
    bool unsupported = false;
    if (!nextDataLine(line) || !nextToken(line, keyword) || !isOffKeyword(keyword, unsupported))
        fail("not an OFF file: it must start with 'OFF' (or COFF, NOFF, ...)");
    if (unsupported)
        fail("'" + std::string(keyword) + "' (4D or n-dimensional OFF) is not supported; only 3D OFF is");
    std::string_view first;
    if (!nextToken(line, first) && (!nextDataLine(line) || !nextToken(line, first)))
        fail("the OFF header has no vertex and face counts");
    if (first == "BINARY")
        fail("binary OFF is not supported; convert it to text OFF or PLY");
    std::string_view second;
    if (!nextToken(line, second))
        fail("the OFF header needs a vertex count and a face count, e.g. '8 6 12'");
    m_vertexCount = parseCount(first, "vertex");
    m_faceCount = parseCount(second, "face");
    if (m_faceCount == 0)
        fail("the file contains no faces (the header declares 0); point clouds cannot be trimmed");
}

void OffParser::parseVertex(std::size_t v)
{
    std::string_view line;
    if (!nextDataLine(line))
        throw MeshLoadError(m_name, "truncated: the header declares " + std::to_string(m_vertexCount) +
                                        " vertices, but the file ends after " + std::to_string(v));
    double xyz[3];
    for (int c = 0; c < 3; ++c) {
        std::string_view token;
        if (!nextToken(line, token))
            fail("a vertex needs 3 coordinates (x y z), but this line has " + std::to_string(c),
                 "vertex " + std::to_string(v));
        if (!parseDouble(token, xyz[c]))
            fail("'" + std::string(token) + "' is not a number", "vertex " + std::to_string(v));
        if (!isFiniteFloat(xyz[c]))
            fail("the vertex " + nonFiniteCoordinateReason(xyz[c]), "vertex " + std::to_string(v));
    }
    m_positions.emplace_back(static_cast<float>(xyz[0]), static_cast<float>(xyz[1]), static_cast<float>(xyz[2]));
}

std::uint32_t OffParser::parseIndex(std::string_view token, std::size_t f, std::size_t corner, std::size_t declared)
{
    const std::string element = "face " + std::to_string(f);
    std::int64_t index = 0;
    if (token.empty())
        fail("the face declares " + std::to_string(declared) + " vertices but lists only " + std::to_string(corner),
             element);
    if (!parseInteger(token, index))
        fail("'" + std::string(token) + "' is not a vertex index", element);
    if (index < 0)
        fail("vertex index " + std::to_string(index) + " is negative; OFF indices count from 0", element);
    if (static_cast<std::uint64_t>(index) >= m_vertexCount)
        fail("the face references vertex " + std::to_string(index) + ", but " + vertexCountPhrase(m_vertexCount, true),
             element);
    return static_cast<std::uint32_t>(index);
}

void OffParser::parseFace(std::size_t f)
{
    std::string_view line;
    if (!nextDataLine(line))
        throw MeshLoadError(m_name, "truncated: the header declares " + std::to_string(m_faceCount) +
                                        " faces, but the file ends after " + std::to_string(f));
    std::string_view token;
    std::int64_t n = 0;
    nextToken(line, token);
    if (!parseInteger(token, n))
        fail("'" + std::string(token) + "' is not a vertex count", "face " + std::to_string(f));
    if (n < 3)
        fail("the face has " +
                 countNoun(static_cast<std::uint64_t>(std::max<std::int64_t>(n, 0)), "vertex", "vertices") +
                 "; a face needs at least 3",
             "face " + std::to_string(f));
    for (std::int64_t i = 0; i < n; ++i) {
        if (!nextToken(line, token))
            token = {};
        m_soup.corners.push_back(parseIndex(token, f, static_cast<std::size_t>(i), static_cast<std::size_t>(n)));
    }
    m_soup.closePolygon(); // anything after the indices is a face colour: ignored
}

TriangleMesh OffParser::parse()
{
    parseHeader();
    m_positions.reserve(cappedReserve(m_vertexCount, m_lines.bytesRemaining(), 6));
    for (std::size_t v = 0; v < m_vertexCount; ++v)
        parseVertex(v);
    const std::size_t faces = cappedReserve(m_faceCount, m_lines.bytesRemaining(), 8);
    m_soup.starts.reserve(faces + 1);
    m_soup.corners.reserve(3 * faces);
    for (std::size_t f = 0; f < m_faceCount; ++f)
        parseFace(f);
    TriangleMesh mesh;
    mesh.triangles = triangulatePolygons(m_positions, m_soup);
    mesh.positions = std::move(m_positions);
    return mesh;
}

} // namespace

TriangleMesh readOff(std::string_view text, const std::string& displayName)
{
    rejectBinaryData(text, displayName, "OFF");
    OffParser parser(withoutUtf8Bom(text), displayName);
    return parser.parse();
}

} // namespace trimlab
