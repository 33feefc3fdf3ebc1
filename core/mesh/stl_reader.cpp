#include "core/mesh/stl_reader.h"

#include "core/mesh/byte_cursor.h"
#include "core/mesh/mesh_load_error.h"
#include "core/mesh/polygon_triangulation.h"
#include "core/mesh/reader_support.h"
#include "core/mesh/text_scanner.h"
#include "core/mesh/vertex_welding.h"

#include <algorithm>
#include <cctype>

namespace trimlab {

namespace {

constexpr std::size_t kBinaryHeaderBytes = 84; // 80-byte header + uint32 triangle count
constexpr std::size_t kBinaryFacetBytes = 50;  // normal, 3 vertices, uint16 attribute

bool equalsIgnoreCase(std::string_view a, std::string_view b)
{
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

bool startsWithSolid(std::string_view bytes)
{
    TokenStream tokens(bytes.substr(0, 256));
    std::string_view first;
    return tokens.next(first) && equalsIgnoreCase(first, "solid");
}

bool beginsAsText(std::string_view bytes)
{
    const std::string_view head = bytes.substr(0, 512);
    return std::none_of(head.begin(), head.end(), [](char c) {
        const auto u = static_cast<unsigned char>(c);
        return u < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != '\v';
    });
}

std::uint64_t declaredTriangles(std::string_view bytes)
{
    return decodeScalar<std::uint32_t>(bytes.data() + 80, std::endian::little);
}

bool isExactBinarySize(std::string_view bytes)
{
    return bytes.size() >= kBinaryHeaderBytes &&
           bytes.size() == kBinaryHeaderBytes + kBinaryFacetBytes * declaredTriangles(bytes);
}

TriangleMesh readBinaryStl(std::string_view bytes, const std::string& name)
{
    if (bytes.size() < kBinaryHeaderBytes)
        throw MeshLoadError(name, "not an STL file: too short for binary STL (" + std::to_string(bytes.size()) +
                                      " bytes; the header alone takes 84) and it does not start with 'solid'");
    const std::uint64_t n = declaredTriangles(bytes);
    if (n == 0)
        throw MeshLoadError(name, "the file contains no faces (the binary STL header declares 0 triangles)");
    const std::uint64_t expected = kBinaryHeaderBytes + kBinaryFacetBytes * n;
    if (bytes.size() < expected)
        throw MeshLoadError(name, "truncated binary STL: the header declares " + std::to_string(n) +
                                      " triangles, which need " + std::to_string(expected) +
                                      " bytes, but the file has only " + std::to_string(bytes.size()));
    // Data after the last triangle means the count or the file is wrong; only a trailing
    // line break or padding of blanks (some writers add one) is tolerated.
    if (const std::string_view rest = bytes.substr(expected);
        rest.find_first_not_of(std::string_view(" \t\r\n\0", 5)) != std::string_view::npos)
        throw MeshLoadError(name, "the binary STL header declares " + std::to_string(n) + " triangles (" +
                                      std::to_string(expected) + " bytes), but the file has " +
                                      std::to_string(bytes.size()) + " bytes: " + std::to_string(rest.size()) +
                                      " bytes follow the last triangle");
    TriangleMesh soup;
    soup.positions.reserve(3 * n);
    soup.triangles.reserve(n);
    for (std::uint64_t i = 0; i < n; ++i) {
        const std::size_t offset = kBinaryHeaderBytes + kBinaryFacetBytes * i;
        ByteCursor cursor(bytes, offset + 12, std::endian::little); // skip the normal
        float xyz[9];
        for (float& value : xyz)
            cursor.read(value); // in bounds: checked against `expected` above
        for (const float value : xyz) {
            if (!isFiniteFloat(value))
                throw MeshLoadError(
                    name, "the triangle " + nonFiniteCoordinateReason(value),
                    {.line = 0,
                     .element = "triangle " + std::to_string(i) + " (byte offset " + std::to_string(offset) + ")"});
        }
        const auto base = static_cast<std::uint32_t>(soup.positions.size());
        for (int c = 0; c < 3; ++c)
            soup.positions.emplace_back(xyz[3 * c], xyz[3 * c + 1], xyz[3 * c + 2]);
        soup.triangles.emplace_back(base, base + 1, base + 2);
    }
    return weldIdenticalVertices(soup);
}

// ASCII STL: solid NAME { facet normal nx ny nz / outer loop / vertex x y z ×3 / endloop /
// endfacet }* endsolid NAME, possibly several solids in a row. Keywords are case-insensitive.
class AsciiStlParser {
public:
    AsciiStlParser(std::string_view text, const std::string& name) : m_tokens(text), m_name(name) {}

    TriangleMesh parse();

private:
    [[noreturn]] void fail(const std::string& reason) const
    {
        throw MeshLoadError(m_name, reason, {.line = m_tokens.line(), .element = {}});
    }
    std::string_view nextOrTruncated(std::string_view expected);
    void expect(std::string_view keyword);
    void skipRestOfLine(std::size_t line);
    void parseFacet();
    glm::vec3 parseVertex();

    TokenStream m_tokens;
    const std::string& m_name;
    std::string_view m_pending; // the token after the one just handled ("" at the end)
    std::vector<glm::vec3> m_positions;
    std::vector<glm::uvec3> m_triangles;
};

std::string_view AsciiStlParser::nextOrTruncated(std::string_view expected)
{
    std::string_view token;
    if (!m_tokens.next(token))
        throw MeshLoadError(m_name, "truncated ASCII STL: the file ends where '" + std::string(expected) +
                                        "' was expected (after " + countNoun(m_triangles.size(), "facet", "facets") +
                                        ")");
    return token;
}

void AsciiStlParser::expect(std::string_view keyword)
{
    const std::string_view token = nextOrTruncated(keyword);
    if (!equalsIgnoreCase(token, keyword))
        fail("expected '" + std::string(keyword) + "', found '" + std::string(token.substr(0, 40)) + "'");
}

void AsciiStlParser::skipRestOfLine(std::size_t line)
{
    m_pending = {};
    std::string_view token;
    while (m_tokens.next(token)) {
        if (m_tokens.line() != line) {
            m_pending = token;
            return;
        }
    }
}

glm::vec3 AsciiStlParser::parseVertex()
{
    double xyz[3];
    for (double& value : xyz) {
        const std::string_view token = nextOrTruncated("a coordinate");
        if (!parseDouble(token, value))
            fail("'" + std::string(token.substr(0, 40)) + "' is not a number");
        if (!isFiniteFloat(value))
            throw MeshLoadError(m_name, "the facet " + nonFiniteCoordinateReason(value),
                                {.line = m_tokens.line(), .element = "facet " + std::to_string(m_triangles.size())});
    }
    return {static_cast<float>(xyz[0]), static_cast<float>(xyz[1]), static_cast<float>(xyz[2])};
}

void AsciiStlParser::parseFacet()
{
    expect("normal");
    for (int i = 0; i < 3; ++i)
        nextOrTruncated("a normal component"); // ignored: orientation comes from vertex order
    expect("outer");
    expect("loop");
    std::vector<std::uint32_t> polygon;
    for (;;) {
        const std::string_view token = nextOrTruncated("endloop");
        if (equalsIgnoreCase(token, "endloop"))
            break;
        if (!equalsIgnoreCase(token, "vertex"))
            fail("expected 'vertex' or 'endloop', found '" + std::string(token.substr(0, 40)) + "'");
        polygon.push_back(static_cast<std::uint32_t>(m_positions.size()));
        m_positions.push_back(parseVertex());
    }
    if (polygon.size() < 3)
        fail("facet " + std::to_string(m_triangles.size()) + " has " + countNoun(polygon.size(), "vertex", "vertices") +
             "; a facet needs 3");
    expect("endfacet");
    triangulatePolygon(m_positions, polygon, m_triangles);
}

TriangleMesh AsciiStlParser::parse()
{
    expect("solid");
    skipRestOfLine(m_tokens.line()); // the solid's name
    for (;;) {
        if (m_pending.empty())
            throw MeshLoadError(m_name, "truncated ASCII STL: the file ends without 'endsolid'");
        if (equalsIgnoreCase(m_pending, "facet")) {
            parseFacet();
            m_pending = nextOrTruncated("facet' or 'endsolid");
        } else if (equalsIgnoreCase(m_pending, "endsolid")) {
            skipRestOfLine(m_tokens.line());
            if (m_pending.empty())
                break;
            if (!equalsIgnoreCase(m_pending, "solid"))
                fail("expected 'solid' or the end of the file after 'endsolid', found '" +
                     std::string(m_pending.substr(0, 40)) + "'");
            skipRestOfLine(m_tokens.line());
        } else {
            fail("expected 'facet' or 'endsolid', found '" + std::string(m_pending.substr(0, 40)) + "'");
        }
    }
    if (m_triangles.empty())
        throw MeshLoadError(m_name, "the file contains no faces (an ASCII STL without facets)");
    TriangleMesh soup;
    soup.positions = std::move(m_positions);
    soup.triangles = std::move(m_triangles);
    return weldIdenticalVertices(soup);
}

} // namespace

TriangleMesh readStl(std::string_view bytes, const std::string& displayName)
{
    if (isExactBinarySize(bytes))
        return readBinaryStl(bytes, displayName);
    const std::string_view text = withoutUtf8Bom(bytes);
    if (startsWithSolid(text) && beginsAsText(text)) {
        rejectBinaryData(text, displayName, "ASCII STL");
        AsciiStlParser parser(text, displayName);
        return parser.parse();
    }
    return readBinaryStl(bytes, displayName);
}

} // namespace trimlab
