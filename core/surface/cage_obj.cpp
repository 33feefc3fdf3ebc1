#include "core/surface/cage_obj.h"

#include "core/mesh/gzip_input.h"
#include "core/mesh/mesh_io.h"
#include "core/mesh/mesh_load_error.h"
#include "core/mesh/obj_line_parser.h"
#include "core/mesh/reader_support.h"
#include "core/mesh/text_scanner.h"

#include <iterator>
#include <cmath>
#include <cstdio>

namespace trimlab {

namespace {

// Parse state for one cage file. Face indices are range-checked at the end, because a
// face may name vertices defined after it.
class CageObjParser : private ObjLineParser {
public:
    CageObjParser(const std::string& displayName, SubdivisionScheme scheme) : ObjLineParser(displayName)
    {
        m_cage.scheme = scheme;
    }

    void parseLine(std::string_view line, std::size_t lineNumber);
    SubdivisionCage finish();

private:
    void parseTag(std::string_view rest);
    void addTag(std::string_view name, const std::vector<std::int64_t>& ints, const std::vector<double>& floats);
    [[nodiscard]] std::size_t lineOf(const std::optional<CageElement>& element) const;

    SubdivisionCage m_cage;
    std::vector<std::size_t> m_faceLines;   // line of each face
    std::vector<std::size_t> m_creaseLines; // line of each crease
    std::vector<std::size_t> m_cornerLines; // line of each corner
};

void CageObjParser::parseLine(std::string_view line, std::size_t lineNumber)
{
    setLine(lineNumber);
    std::string_view rest = stripComment(line);
    std::string_view keyword;
    if (!nextToken(rest, keyword))
        return;
    if (keyword == "v") {
        m_cage.positions.push_back(parseVertexLine(rest, m_cage.positions.size()));
    } else if (keyword == "f") {
        m_cage.faceSizes.push_back(parseFaceLine(rest, m_cage.positions.size(), m_cage.faceIndices));
        m_faceLines.push_back(this->line());
    } else if (keyword == "t") {
        parseTag(rest);
    }
    // vt, vn, o, g, s, usemtl, mtllib, l, p and unknown keywords carry nothing a cage uses.
}

// `t NAME nInts/nFloats/nStrings int... float... string...` as in OpenSubdiv's shape files.
void CageObjParser::parseTag(std::string_view rest)
{
    std::string_view name, counts;
    if (!nextToken(rest, name) || !nextToken(rest, counts))
        fail("a tag needs a name and counts, e.g. 't crease 2/1/0 0 1 10'");
    std::int64_t n[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i) {
        const std::size_t slash = counts.find('/');
        if (!parseInteger(counts.substr(0, slash), n[i]) || n[i] < 0 || (i < 2) == (slash == std::string_view::npos))
            fail("tag counts '" + std::string(counts) + "' are not of the form ints/floats/strings, e.g. 2/1/0");
        counts = slash == std::string_view::npos ? std::string_view() : counts.substr(slash + 1);
    }
    std::vector<std::int64_t> ints;
    std::vector<double> floats;
    std::string_view token;
    for (std::int64_t i = 0; i < n[0] + n[1]; ++i) {
        if (!nextToken(rest, token))
            fail("tag '" + std::string(name) + "' declares " + std::to_string(n[0]) + " integers and " +
                 std::to_string(n[1]) + " numbers, but the line ends after " + std::to_string(i));
        double value = 0.0;
        std::int64_t index = 0;
        if (i < n[0] ? !parseInteger(token, index) : !parseDouble(token, value))
            fail("'" + std::string(token) + "' is not " + (i < n[0] ? "an integer" : "a number") + " in tag '" +
                 std::string(name) + "'");
        if (i < n[0])
            ints.push_back(index);
        else
            floats.push_back(value);
    }
    if (n[2] != 0 || nextToken(rest, token))
        fail("tag '" + std::string(name) +
             "' has more values than its counts declare (string arguments are not supported)");
    addTag(name, ints, floats);
}

void CageObjParser::addTag(std::string_view name, const std::vector<std::int64_t>& ints,
                           const std::vector<double>& floats)
{
    const bool crease = name == "crease";
    if (!crease && name != "corner")
        fail("unsupported tag '" + std::string(name) + "'; cages support 't crease' and 't corner'");
    const std::size_t arity = crease ? 2 : 1;
    const std::size_t elements = ints.size() / arity;
    if (ints.empty() || ints.size() % arity != 0)
        fail(crease ? "a crease tag needs vertex pairs (an even, non-zero number of integers)"
                    : "a corner tag needs at least one vertex");
    if (floats.size() != 1 && floats.size() != elements)
        fail("tag '" + std::string(name) + "' needs 1 sharpness or one per " + (crease ? "edge" : "vertex") + " (" +
             std::to_string(elements) + "), not " + std::to_string(floats.size()));
    for (const std::int64_t v : ints)
        if (v < 0 || v > std::int64_t(kMaxMeshVertices))
            fail("tag vertex " + std::to_string(v) + " is invalid; tag indices count from 0");
    for (std::size_t e = 0; e < elements; ++e) {
        const double s = floats.size() == 1 ? floats[0] : floats[e];
        if (!std::isfinite(s) || s < 0.0) {
            char text[32];
            std::snprintf(text, sizeof text, "%g", s);
            fail("sharpness " + std::string(text) + " is invalid; use a number >= 0 (10 or more is infinitely sharp)");
        }
        if (crease) {
            m_cage.creases.push_back({std::uint32_t(ints[2 * e]), std::uint32_t(ints[2 * e + 1]), float(s)});
            m_creaseLines.push_back(line());
        } else {
            m_cage.corners.push_back({std::uint32_t(ints[e]), float(s)});
            m_cornerLines.push_back(line());
        }
    }
}

SubdivisionCage CageObjParser::finish()
{
    if (m_cage.faceCount() == 0)
        throw MeshLoadError(name(), "the file contains no faces (" +
                                        countNoun(m_cage.positions.size(), "vertex", "vertices") +
                                        ", but no 'f' lines); a cage needs polygons");
    std::size_t start = 0;
    for (std::size_t f = 0; f < m_cage.faceCount(); ++f) {
        for (std::size_t k = start; k < start + m_cage.faceSizes[f]; ++k) {
            if (m_cage.faceIndices[k] >= m_cage.positions.size())
                throw MeshLoadError(name(),
                                    "face " + std::to_string(f + 1) + " references vertex " +
                                        std::to_string(std::uint64_t(m_cage.faceIndices[k]) + 1) + ", but " +
                                        vertexCountPhrase(m_cage.positions.size(), false),
                                    {.line = m_faceLines[f], .element = {}});
        }
        start += m_cage.faceSizes[f];
    }
    try {
        validateCage(m_cage);
    } catch (const SubdivisionError& e) {
        throw MeshLoadError(name(), e.what(), {.line = lineOf(e.element()), .element = {}});
    }
    return std::move(m_cage);
}

std::size_t CageObjParser::lineOf(const std::optional<CageElement>& element) const
{
    if (!element)
        return 0;
    switch (element->kind) {
    case CageElement::Kind::Face:
        return m_faceLines[element->index];
    case CageElement::Kind::Crease:
        return m_creaseLines[element->index];
    case CageElement::Kind::Corner:
        return m_cornerLines[element->index];
    }
    return 0;
}

} // namespace

SubdivisionCage readCageObj(std::string_view text, const std::string& displayName, SubdivisionScheme scheme)
{
    rejectBinaryData(text, displayName, "OBJ");
    CageObjParser parser(displayName, scheme);
    LineScanner lines(withoutUtf8Bom(text));
    std::string_view line;
    while (lines.next(line))
        parser.parseLine(line, lines.lineNumber());
    return parser.finish();
}

SubdivisionCage loadCageObj(const std::filesystem::path& path, SubdivisionScheme scheme)
{
    const std::string name = path.string();
    std::string bytes = readMeshInputFile(path, name);
    if (bytes.empty())
        throw MeshLoadError(name, "the file is empty (0 bytes)");
    if (hasGzipMagic(bytes))
        bytes = gunzip(bytes, name, kMaxMeshInputBytes);
    return readCageObj(bytes, name, scheme);
}

} // namespace trimlab
