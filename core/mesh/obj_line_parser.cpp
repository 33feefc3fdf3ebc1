#include "core/mesh/obj_line_parser.h"

#include "core/mesh/mesh_load_error.h"
#include "core/mesh/reader_support.h"
#include "core/mesh/text_scanner.h"

namespace trimlab {

void ObjLineParser::fail(const std::string& reason) const
{
    throw MeshLoadError(m_name, reason, {.line = m_line, .element = {}});
}

glm::dvec3 ObjLineParser::parseVertexLine(std::string_view rest, std::size_t vertexCount) const
{
    glm::dvec3 p(0.0);
    for (int c = 0; c < 3; ++c) {
        std::string_view token;
        if (!nextToken(rest, token))
            fail("a vertex needs 3 coordinates (v x y z), but this line has " + std::to_string(c));
        if (!parseDouble(token, p[c]))
            fail("'" + std::string(token) + "' is not a number");
        if (!isFiniteFloat(p[c]))
            fail("vertex " + std::to_string(vertexCount + 1) + ' ' + nonFiniteCoordinateReason(p[c]));
    }
    if (vertexCount >= kMaxMeshVertices)
        fail("too many vertices; at most 4294967295 are supported");
    return p;
}

std::uint32_t ObjLineParser::parseCorner(std::string_view corner, std::size_t vertexCount) const
{
    const std::string_view vertexPart = corner.substr(0, corner.find('/'));
    std::int64_t index = 0;
    if (!parseInteger(vertexPart, index))
        fail("'" + std::string(corner) + "' is not a valid face corner (expected v, v/vt, v//vn or v/vt/vn)");
    const auto defined = static_cast<std::int64_t>(vertexCount);
    if (index == 0)
        fail("vertex index 0 is invalid: OBJ indices count from 1 (or back from -1)");
    if (index < 0) {
        if (index < -defined) // not -index > defined: -INT64_MIN overflows
            fail("face references vertex " + std::to_string(index) + " (counting back), but only " +
                 countNoun(static_cast<std::uint64_t>(defined), "vertex is", "vertices are") +
                 " defined before this line");
        return static_cast<std::uint32_t>(defined + index);
    }
    if (static_cast<std::uint64_t>(index) > kMaxMeshVertices)
        fail("face references vertex " + std::to_string(index) + ", far beyond the supported vertex count");
    return static_cast<std::uint32_t>(index - 1);
}

std::uint32_t ObjLineParser::parseFaceLine(std::string_view rest, std::size_t vertexCount,
                                           std::vector<std::uint32_t>& indices) const
{
    std::string_view token;
    std::uint32_t count = 0;
    while (nextToken(rest, token)) {
        indices.push_back(parseCorner(token, vertexCount));
        ++count;
    }
    if (count < 3)
        fail("the face has " + countNoun(count, "vertex", "vertices") + "; a face needs at least 3");
    return count;
}

} // namespace trimlab
