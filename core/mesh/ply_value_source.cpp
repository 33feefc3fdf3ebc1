#include "core/mesh/ply_value_source.h"

#include <cstdint>

namespace trimlab {

namespace {

std::endian byteOrder(PlyEncoding encoding)
{
    return encoding == PlyEncoding::BinaryBigEndian ? std::endian::big : std::endian::little;
}

template <class T>
PlyValueSource::Status readAs(ByteCursor& cursor, double& value)
{
    T raw{};
    if (!cursor.read(raw))
        return PlyValueSource::Status::End;
    value = static_cast<double>(raw);
    return PlyValueSource::Status::Ok;
}

} // namespace

PlyValueSource::PlyValueSource(std::string_view bytes, const PlyHeader& header)
    : m_ascii(header.encoding == PlyEncoding::Ascii),
      m_tokens(bytes.substr(std::min(header.dataOffset, bytes.size())), header.lineCount + 1),
      m_cursor(bytes, header.dataOffset, byteOrder(header.encoding))
{
}

PlyValueSource::Status PlyValueSource::read(PlyScalarType type, double& value)
{
    if (!m_ascii)
        return readBinary(type, value);
    if (!m_tokens.next(m_lastToken))
        return Status::End;
    if (isPlyIntegerType(type)) {
        std::int64_t integer = 0;
        if (!parseInteger(m_lastToken, integer))
            return Status::Malformed;
        value = static_cast<double>(integer);
        return Status::Ok;
    }
    return parseDouble(m_lastToken, value) ? Status::Ok : Status::Malformed;
}

PlyValueSource::Status PlyValueSource::readBinary(PlyScalarType type, double& value)
{
    m_valueOffset = m_cursor.offset();
    switch (type) {
    case PlyScalarType::Int8:
        return readAs<std::int8_t>(m_cursor, value);
    case PlyScalarType::UInt8:
        return readAs<std::uint8_t>(m_cursor, value);
    case PlyScalarType::Int16:
        return readAs<std::int16_t>(m_cursor, value);
    case PlyScalarType::UInt16:
        return readAs<std::uint16_t>(m_cursor, value);
    case PlyScalarType::Int32:
        return readAs<std::int32_t>(m_cursor, value);
    case PlyScalarType::UInt32:
        return readAs<std::uint32_t>(m_cursor, value);
    case PlyScalarType::Float32:
        return readAs<float>(m_cursor, value);
    case PlyScalarType::Float64:
        return readAs<double>(m_cursor, value);
    }
    return Status::End;
}

bool PlyValueSource::couldHold(double count, PlyScalarType type) const
{
    const double bytesPerValue = m_ascii ? 2.0 : static_cast<double>(plyScalarSize(type));
    return count * bytesPerValue <= static_cast<double>(bytesRemaining()) + 1.0;
}

std::size_t PlyValueSource::line() const
{
    return m_ascii ? m_tokens.line() : 0;
}

std::string PlyValueSource::position() const
{
    return m_ascii ? std::string() : "byte offset " + std::to_string(m_valueOffset);
}

std::string PlyValueSource::trailingData() const
{
    if (m_ascii) {
        TokenStream probe = m_tokens;
        std::string_view token;
        if (!probe.next(token))
            return {};
        return "the token '" + std::string(token.substr(0, 32)) + "' on line " + std::to_string(probe.line());
    }
    const std::string_view rest = m_cursor.rest();
    if (rest.find_first_not_of(std::string_view(" \t\r\n\0", 5)) == std::string_view::npos)
        return {};
    return std::to_string(rest.size()) + " bytes";
}

std::size_t PlyValueSource::bytesRemaining() const
{
    return m_ascii ? m_tokens.bytesRemaining() : m_cursor.remaining();
}

} // namespace trimlab
