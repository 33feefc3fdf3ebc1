#pragma once
/// \file
/// The header of a PLY file: encoding, elements and their properties, where the data
/// starts. See http://paulbourke.net/dataformats/ply/ for the format.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace trimlab {

enum class PlyEncoding { Ascii, BinaryLittleEndian, BinaryBigEndian };

/// The scalar types of PLY (both the old names "uchar" and the sized names "uint8").
enum class PlyScalarType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

/// Size in bytes of one value of `type` in the binary encodings.
[[nodiscard]] std::size_t plyScalarSize(PlyScalarType type);
[[nodiscard]] bool isPlyIntegerType(PlyScalarType type);

/// `property TYPE NAME` (scalar) or `property list COUNTTYPE TYPE NAME` (list).
struct PlyProperty {
    std::string name;
    PlyScalarType type = PlyScalarType::Float32; ///< the value type (list items for lists)
    bool isList = false;
    PlyScalarType countType = PlyScalarType::UInt8; ///< lists only; always an integer type
};

/// `element NAME COUNT` followed by its properties.
struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
    std::size_t headerLine = 0; ///< 1-based line of the `element` statement

    /// Index of the property called `name`, or -1.
    [[nodiscard]] int findProperty(std::string_view name) const;
    /// Bytes per item in a binary encoding when no property is a list, else 0.
    [[nodiscard]] std::size_t fixedBinarySize() const;
};

struct PlyHeader {
    PlyEncoding encoding = PlyEncoding::Ascii;
    std::vector<PlyElement> elements;
    std::size_t dataOffset = 0; ///< byte offset of the first byte after `end_header`'s line
    std::size_t lineCount = 0;  ///< number of header lines (ASCII data starts on the next)
};

/// Parses the header at the start of `bytes`. Throws MeshLoadError naming `displayName`
/// and the header line for a missing "ply" magic line, missing or unknown `format`, an
/// unknown property type, a property outside an element, a malformed statement, or a
/// missing `end_header`. `comment` and `obj_info` lines are skipped.
[[nodiscard]] PlyHeader parsePlyHeader(std::string_view bytes, const std::string& displayName);

} // namespace trimlab
