#include "core/mesh/ply_reader.h"

#include "core/mesh/mesh_load_error.h"
#include "core/mesh/ply_header.h"
#include "core/mesh/ply_value_source.h"
#include "core/mesh/polygon_triangulation.h"
#include "core/mesh/reader_support.h"

#include <cmath>

namespace trimlab {

namespace {

// Where the vertex coordinates and face indices live in the header.
struct PlyLayout {
    int vertexElement = -1;
    int faceElement = -1;
    int coordinate[3] = {-1, -1, -1}; // property index of x, y, z
    int faceList = -1;                // property index of vertex_indices
};

int findUniqueElement(const PlyHeader& header, std::string_view name, const std::string& displayName)
{
    int found = -1;
    for (std::size_t i = 0; i < header.elements.size(); ++i) {
        if (header.elements[i].name != name)
            continue;
        if (found >= 0)
            throw MeshLoadError(displayName, "the header declares more than one '" + std::string(name) + "' element",
                                {.line = header.elements[i].headerLine, .element = {}});
        found = static_cast<int>(i);
    }
    return found;
}

void findCoordinates(const PlyElement& vertex, PlyLayout& layout, const std::string& displayName)
{
    const char* names[3] = {"x", "y", "z"};
    for (int c = 0; c < 3; ++c) {
        layout.coordinate[c] = vertex.findProperty(names[c]);
        if (layout.coordinate[c] < 0 || vertex.properties[layout.coordinate[c]].isList)
            throw MeshLoadError(displayName,
                                std::string("the vertex element has no scalar property '") + names[c] +
                                    "'; vertices need x, y and z",
                                {.line = vertex.headerLine, .element = {}});
    }
    if (vertex.count > kMaxMeshVertices)
        throw MeshLoadError(displayName,
                            "the header declares " + std::to_string(vertex.count) +
                                " vertices; at most 4294967295 are supported",
                            {.line = vertex.headerLine, .element = {}});
}

PlyLayout findLayout(const PlyHeader& header, const std::string& displayName)
{
    PlyLayout layout;
    layout.vertexElement = findUniqueElement(header, "vertex", displayName);
    layout.faceElement = findUniqueElement(header, "face", displayName);
    if (layout.faceElement < 0 || header.elements[layout.faceElement].count == 0)
        throw MeshLoadError(displayName, "the file contains no faces (no 'face' element, or its count is 0); "
                                         "point clouds cannot be trimmed");
    if (layout.vertexElement < 0)
        throw MeshLoadError(displayName, "the header declares no 'vertex' element");
    findCoordinates(header.elements[layout.vertexElement], layout, displayName);
    const PlyElement& face = header.elements[layout.faceElement];
    layout.faceList = face.findProperty("vertex_indices");
    if (layout.faceList < 0)
        layout.faceList = face.findProperty("vertex_index");
    if (layout.faceList < 0 || !face.properties[layout.faceList].isList)
        throw MeshLoadError(displayName, "the face element has no list property 'vertex_indices' (or 'vertex_index')",
                            {.line = face.headerLine, .element = {}});
    return layout;
}

// Walks the body element by element, keeping vertices and faces, skipping the rest.
class PlyBodyReader {
public:
    PlyBodyReader(std::string_view bytes, const PlyHeader& header, const PlyLayout& layout,
                  const std::string& displayName)
        : m_header(header),
          m_layout(layout),
          m_name(displayName),
          m_source(bytes, header),
          m_vertexCount(header.elements[layout.vertexElement].count)
    {
    }

    TriangleMesh read();

private:
    double value(PlyScalarType type, const PlyElement& element, std::uint64_t item);
    std::uint64_t listCount(const PlyProperty& property, const PlyElement& element, std::uint64_t item);
    void reserveFor(const PlyElement& element, bool isVertex);
    void readVertex(const PlyElement& element, std::uint64_t item);
    void readFace(const PlyElement& element, std::uint64_t item);
    void skipItem(const PlyElement& element, std::uint64_t item);
    void readFaceIndex(const PlyProperty& list, const PlyElement& element, std::uint64_t item);
    [[noreturn]] void failAt(const std::string& reason, std::uint64_t item, const PlyElement& element) const;

    const PlyHeader& m_header;
    const PlyLayout& m_layout;
    const std::string& m_name;
    PlyValueSource m_source;
    std::uint64_t m_vertexCount;
    std::vector<glm::vec3> m_positions;
    PolygonSoup m_soup;
};

void PlyBodyReader::failAt(const std::string& reason, std::uint64_t item, const PlyElement& element) const
{
    std::string where = element.name + ' ' + std::to_string(item);
    const std::string position = m_source.position();
    if (!position.empty())
        where += " (" + position + ")";
    throw MeshLoadError(m_name, reason, {.line = m_source.line(), .element = where});
}

double PlyBodyReader::value(PlyScalarType type, const PlyElement& element, std::uint64_t item)
{
    double result = 0.0;
    switch (m_source.read(type, result)) {
    case PlyValueSource::Status::Ok:
        return result;
    case PlyValueSource::Status::End:
        throw MeshLoadError(m_name, "truncated: the data ends at " + element.name + ' ' + std::to_string(item) +
                                        ", but the header declares " + std::to_string(element.count) + " '" +
                                        element.name + "' elements");
    case PlyValueSource::Status::Malformed:
        break;
    }
    failAt("'" + std::string(m_source.lastToken()) + "' is not a valid " +
               (isPlyIntegerType(type) ? "integer" : "number"),
           item, element);
}

std::uint64_t PlyBodyReader::listCount(const PlyProperty& property, const PlyElement& element, std::uint64_t item)
{
    const double count = value(property.countType, element, item);
    if (count < 0.0)
        failAt("list '" + property.name + "' has a negative length (" + std::to_string(count) + ")", item, element);
    if (!m_source.couldHold(count, property.type))
        throw MeshLoadError(m_name, "truncated: " + element.name + ' ' + std::to_string(item) + " declares " +
                                        std::to_string(static_cast<std::uint64_t>(count)) + " entries in list '" +
                                        property.name + "', but only " + std::to_string(m_source.bytesRemaining()) +
                                        " bytes of data remain");
    return static_cast<std::uint64_t>(count);
}

void PlyBodyReader::readVertex(const PlyElement& element, std::uint64_t item)
{
    double xyz[3] = {0.0, 0.0, 0.0};
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        if (property.isList) {
            const std::uint64_t n = listCount(property, element, item);
            for (std::uint64_t i = 0; i < n; ++i)
                value(property.type, element, item);
            continue;
        }
        const double v = value(property.type, element, item);
        for (int c = 0; c < 3; ++c) {
            if (static_cast<int>(p) != m_layout.coordinate[c])
                continue;
            if (!isFiniteFloat(v))
                failAt("the vertex " + nonFiniteCoordinateReason(v), item, element);
            xyz[c] = v;
        }
    }
    m_positions.emplace_back(static_cast<float>(xyz[0]), static_cast<float>(xyz[1]), static_cast<float>(xyz[2]));
}

void PlyBodyReader::readFaceIndex(const PlyProperty& list, const PlyElement& element, std::uint64_t item)
{
    const double index = value(list.type, element, item);
    if (index != std::floor(index))
        failAt("vertex index " + std::to_string(index) + " is not an integer", item, element);
    if (index < 0.0)
        failAt("vertex index " + std::to_string(static_cast<std::int64_t>(index)) +
                   " is negative; PLY vertex indices count from 0",
               item, element);
    if (index >= static_cast<double>(m_vertexCount))
        failAt("the face references vertex " + std::to_string(static_cast<std::uint64_t>(index)) + ", but " +
                   vertexCountPhrase(m_vertexCount, true),
               item, element);
    m_soup.corners.push_back(static_cast<std::uint32_t>(index));
}

void PlyBodyReader::readFace(const PlyElement& element, std::uint64_t item)
{
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        if (!property.isList) {
            value(property.type, element, item);
            continue;
        }
        const std::uint64_t n = listCount(property, element, item);
        const bool isIndexList = static_cast<int>(p) == m_layout.faceList;
        if (isIndexList && n < 3)
            failAt("the face has " + countNoun(n, "vertex", "vertices") + "; a face needs at least 3", item, element);
        for (std::uint64_t i = 0; i < n; ++i) {
            if (isIndexList)
                readFaceIndex(property, element, item);
            else
                value(property.type, element, item);
        }
    }
    m_soup.closePolygon();
}

void PlyBodyReader::skipItem(const PlyElement& element, std::uint64_t item)
{
    for (const PlyProperty& property : element.properties) {
        const std::uint64_t n = property.isList ? listCount(property, element, item) : 1;
        for (std::uint64_t i = 0; i < n; ++i)
            value(property.type, element, item);
    }
}

void PlyBodyReader::reserveFor(const PlyElement& element, bool isVertex)
{
    const bool ascii = m_header.encoding == PlyEncoding::Ascii;
    const std::size_t fixed = element.fixedBinarySize();
    const std::size_t minBytes = ascii ? 2 * element.properties.size() : (fixed > 0 ? fixed : 4);
    const std::size_t n = cappedReserve(element.count, m_source.bytesRemaining(), minBytes);
    if (isVertex) {
        m_positions.reserve(n);
    } else {
        m_soup.starts.reserve(n + 1);
        m_soup.corners.reserve(3 * n);
    }
}

TriangleMesh PlyBodyReader::read()
{
    for (std::size_t e = 0; e < m_header.elements.size(); ++e) {
        const PlyElement& element = m_header.elements[e];
        if (element.properties.empty())
            continue; // nothing stored per item, whatever the count says
        const bool isVertex = static_cast<int>(e) == m_layout.vertexElement;
        const bool isFace = static_cast<int>(e) == m_layout.faceElement;
        if (isVertex || isFace)
            reserveFor(element, isVertex);
        for (std::uint64_t item = 0; item < element.count; ++item) {
            if (isVertex)
                readVertex(element, item);
            else if (isFace)
                readFace(element, item);
            else
                skipItem(element, item);
        }
    }
    // Data after the last element means a count in the header is wrong.
    if (const std::string trailing = m_source.trailingData(); !trailing.empty())
        throw MeshLoadError(m_name, "the header's elements end before the data does: " + trailing +
                                        " follow the last element (a count in the header is wrong)");
    TriangleMesh mesh;
    mesh.triangles = triangulatePolygons(m_positions, m_soup);
    mesh.positions = std::move(m_positions);
    return mesh;
}

} // namespace

TriangleMesh readPly(std::string_view bytes, const std::string& displayName)
{
    const PlyHeader header = parsePlyHeader(bytes, displayName);
    const PlyLayout layout = findLayout(header, displayName);
    PlyBodyReader reader(bytes, header, layout, displayName);
    return reader.read();
}

} // namespace trimlab
