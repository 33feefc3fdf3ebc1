#include "core/mesh/ply_header.h"

#include "core/mesh/mesh_load_error.h"
#include "core/mesh/text_scanner.h"

#include <array>
#include <optional>
#include <utility>

namespace trimlab {

namespace {

std::optional<PlyScalarType> scalarTypeFromName(std::string_view name)
{
    static constexpr std::array<std::pair<std::string_view, PlyScalarType>, 16> names = {{
        {"char", PlyScalarType::Int8},
        {"int8", PlyScalarType::Int8},
        {"uchar", PlyScalarType::UInt8},
        {"uint8", PlyScalarType::UInt8},
        {"short", PlyScalarType::Int16},
        {"int16", PlyScalarType::Int16},
        {"ushort", PlyScalarType::UInt16},
        {"uint16", PlyScalarType::UInt16},
        {"int", PlyScalarType::Int32},
        {"int32", PlyScalarType::Int32},
        {"uint", PlyScalarType::UInt32},
        {"uint32", PlyScalarType::UInt32},
        {"float", PlyScalarType::Float32},
        {"float32", PlyScalarType::Float32},
        {"double", PlyScalarType::Float64},
        {"float64", PlyScalarType::Float64},
    }};
    for (const auto& [text, type] : names) {
        if (text == name)
            return type;
    }
    return std::nullopt;
}

// Parses the header statements line by line into a PlyHeader.
class HeaderParser {
public:
    HeaderParser(const std::string& displayName, PlyHeader& header) : m_name(displayName), m_header(header) {}

    void parseLine(std::string_view line, std::size_t lineNumber);
    [[nodiscard]] bool sawFormat() const { return m_sawFormat; }

private:
    [[noreturn]] void fail(std::size_t line, const std::string& reason) const
    {
        throw MeshLoadError(m_name, reason, {.line = line, .element = {}});
    }
    void parseFormat(std::string_view rest, std::size_t line);
    void parseElement(std::string_view rest, std::size_t line);
    void parseProperty(std::string_view rest, std::size_t line);
    PlyScalarType parseType(std::string_view token, std::size_t line) const;

    const std::string& m_name;
    PlyHeader& m_header;
    bool m_sawFormat = false;
};

void HeaderParser::parseLine(std::string_view line, std::size_t lineNumber)
{
    std::string_view rest = line;
    std::string_view keyword;
    if (!nextToken(rest, keyword) || keyword == "comment" || keyword == "obj_info")
        return;
    if (keyword == "format")
        parseFormat(rest, lineNumber);
    else if (keyword == "element")
        parseElement(rest, lineNumber);
    else if (keyword == "property")
        parseProperty(rest, lineNumber);
    else
        fail(lineNumber, "unknown PLY header statement '" + std::string(keyword.substr(0, 40)) +
                             "' (is the 'end_header' line missing?)");
}

void HeaderParser::parseFormat(std::string_view rest, std::size_t line)
{
    std::string_view encoding;
    std::string_view version;
    if (!nextToken(rest, encoding) || !nextToken(rest, version))
        fail(line, "malformed format line; expected 'format ascii 1.0' (or binary_little_endian, binary_big_endian)");
    if (encoding == "ascii")
        m_header.encoding = PlyEncoding::Ascii;
    else if (encoding == "binary_little_endian")
        m_header.encoding = PlyEncoding::BinaryLittleEndian;
    else if (encoding == "binary_big_endian")
        m_header.encoding = PlyEncoding::BinaryBigEndian;
    else
        fail(line, "unknown PLY format '" + std::string(encoding) +
                       "'; expected ascii, binary_little_endian or binary_big_endian");
    if (version != "1.0")
        fail(line, "unsupported PLY version '" + std::string(version) + "'; only 1.0 exists");
    m_sawFormat = true;
}

void HeaderParser::parseElement(std::string_view rest, std::size_t line)
{
    std::string_view name;
    std::string_view countText;
    std::int64_t count = 0;
    if (!nextToken(rest, name) || !nextToken(rest, countText))
        fail(line, "malformed element line; expected 'element NAME COUNT'");
    if (!parseInteger(countText, count) || count < 0)
        fail(line, "element '" + std::string(name) + "' has an invalid count '" + std::string(countText) + "'");
    PlyElement element;
    element.name = std::string(name);
    element.count = static_cast<std::uint64_t>(count);
    element.headerLine = line;
    m_header.elements.push_back(std::move(element));
}

PlyScalarType HeaderParser::parseType(std::string_view token, std::size_t line) const
{
    const std::optional<PlyScalarType> type = scalarTypeFromName(token);
    if (!type)
        fail(line, "unknown property type '" + std::string(token) + "'");
    return *type;
}

void HeaderParser::parseProperty(std::string_view rest, std::size_t line)
{
    if (m_header.elements.empty())
        fail(line, "a property is declared before any element");
    PlyProperty property;
    std::string_view first;
    std::string_view name;
    if (!nextToken(rest, first))
        fail(line, "malformed property line; expected 'property TYPE NAME'");
    if (first == "list") {
        std::string_view countType;
        std::string_view itemType;
        if (!nextToken(rest, countType) || !nextToken(rest, itemType) || !nextToken(rest, name))
            fail(line, "malformed list property; expected 'property list COUNTTYPE TYPE NAME'");
        property.isList = true;
        property.countType = parseType(countType, line);
        property.type = parseType(itemType, line);
        if (!isPlyIntegerType(property.countType))
            fail(line, "the count type of list property '" + std::string(name) + "' must be an integer type");
    } else {
        if (!nextToken(rest, name))
            fail(line, "malformed property line; expected 'property TYPE NAME'");
        property.type = parseType(first, line);
    }
    property.name = std::string(name);
    PlyElement& element = m_header.elements.back();
    for (const PlyProperty& earlier : element.properties)
        if (earlier.name == property.name) // which of the two would x be?
            fail(line, "property '" + property.name + "' of element '" + element.name + "' is declared twice");
    element.properties.push_back(std::move(property));
}

std::string_view trimRight(std::string_view line)
{
    while (!line.empty() && (line.back() == ' ' || line.back() == '\t'))
        line.remove_suffix(1);
    return line;
}

} // namespace

std::size_t plyScalarSize(PlyScalarType type)
{
    switch (type) {
    case PlyScalarType::Int8:
    case PlyScalarType::UInt8:
        return 1;
    case PlyScalarType::Int16:
    case PlyScalarType::UInt16:
        return 2;
    case PlyScalarType::Int32:
    case PlyScalarType::UInt32:
    case PlyScalarType::Float32:
        return 4;
    case PlyScalarType::Float64:
        return 8;
    }
    return 0;
}

bool isPlyIntegerType(PlyScalarType type)
{
    return type != PlyScalarType::Float32 && type != PlyScalarType::Float64;
}

int PlyElement::findProperty(std::string_view propertyName) const
{
    for (std::size_t i = 0; i < properties.size(); ++i) {
        if (properties[i].name == propertyName)
            return static_cast<int>(i);
    }
    return -1;
}

std::size_t PlyElement::fixedBinarySize() const
{
    std::size_t size = 0;
    for (const PlyProperty& property : properties) {
        if (property.isList)
            return 0;
        size += plyScalarSize(property.type);
    }
    return size;
}

PlyHeader parsePlyHeader(std::string_view bytes, const std::string& displayName)
{
    LineScanner lines(bytes);
    std::string_view line;
    if (!lines.next(line) || trimRight(line) != "ply")
        throw MeshLoadError(displayName, "not a PLY file: it must start with the line 'ply'");
    PlyHeader header;
    HeaderParser parser(displayName, header);
    while (lines.next(line)) {
        if (trimRight(line) == "end_header") {
            if (!parser.sawFormat())
                throw MeshLoadError(displayName, "the PLY header has no 'format' line");
            header.dataOffset = lines.offset();
            header.lineCount = lines.lineNumber();
            return header;
        }
        parser.parseLine(line, lines.lineNumber());
    }
    throw MeshLoadError(displayName,
                        "the PLY header has no 'end_header' line; the file is truncated or not a PLY file");
}

} // namespace trimlab
