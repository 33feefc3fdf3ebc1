#pragma once
/// \file
/// Reads the values of a PLY body one at a time, hiding the encoding (ASCII tokens or
/// little/big-endian binary) from the element walker in ply_reader.cpp.

#include "core/mesh/byte_cursor.h"
#include "core/mesh/ply_header.h"
#include "core/mesh/text_scanner.h"

#include <cstddef>
#include <string>
#include <string_view>

namespace trimlab {

class PlyValueSource {
public:
    enum class Status {
        Ok,
        End,      ///< no data left (truncated file)
        Malformed ///< ASCII only: a token that is not a number of the declared type
    };

    /// Reads the body of `bytes` described by `header` (from header.dataOffset).
    PlyValueSource(std::string_view bytes, const PlyHeader& header);

    /// Reads one value declared as `type`. Integer types are read exactly (every PLY
    /// integer fits a double); in ASCII an integer-typed token must be an integer.
    Status read(PlyScalarType type, double& value);

    /// True if at least `count` values of `type` could still be present (binary: enough
    /// bytes; ASCII: enough characters for one-digit tokens). Used to reject absurd list
    /// counts before looping over them.
    [[nodiscard]] bool couldHold(double count, PlyScalarType type) const;

    /// Where the last value was read, for error messages: the line (ASCII, else 0) and a
    /// description ("byte offset 1234" for binary, "" for ASCII).
    [[nodiscard]] std::size_t line() const;
    [[nodiscard]] std::string position() const;
    /// The last token read (ASCII), for "'abc' is not a number" messages.
    [[nodiscard]] std::string_view lastToken() const { return m_lastToken; }
    [[nodiscard]] std::size_t bytesRemaining() const;
    /// After the last element: what data follows it ("12 bytes", "the token '7' on line
    /// 9"), or "" when nothing but blanks and line breaks does.
    [[nodiscard]] std::string trailingData() const;

private:
    Status readBinary(PlyScalarType type, double& value);

    bool m_ascii;
    TokenStream m_tokens;
    ByteCursor m_cursor;
    std::size_t m_valueOffset = 0;
    std::string_view m_lastToken;
};

} // namespace trimlab
