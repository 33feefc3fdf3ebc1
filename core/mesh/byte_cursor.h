#pragma once
/// \file
/// Bounds-checked reading of little- or big-endian binary data (binary PLY, STL, GLB and
/// glTF buffers). Reads never go past the end: they fail and consume nothing instead.

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstring>
#include <string_view>
#include <type_traits>

namespace trimlab {

/// Decodes an arithmetic T from sizeof(T) bytes at `bytes` stored in byte order `order`.
/// The caller guarantees the bytes exist.
template <class T>
[[nodiscard]] T decodeScalar(const char* bytes, std::endian order)
{
    static_assert(std::is_arithmetic_v<T>);
    std::array<char, sizeof(T)> raw;
    std::memcpy(raw.data(), bytes, sizeof(T));
    if (order != std::endian::native)
        std::reverse(raw.begin(), raw.end());
    T value;
    std::memcpy(&value, raw.data(), sizeof(T));
    return value;
}

/// A read position in a byte buffer with a fixed byte order.
class ByteCursor {
public:
    ByteCursor(std::string_view data, std::size_t offset, std::endian order)
        : m_data(data), m_pos(std::min(offset, data.size())), m_order(order)
    {
    }

    [[nodiscard]] std::size_t offset() const { return m_pos; }
    [[nodiscard]] std::size_t remaining() const { return m_data.size() - m_pos; }
    /// The bytes not read yet.
    [[nodiscard]] std::string_view rest() const { return m_data.substr(m_pos); }

    /// Reads one T; false (nothing consumed) when fewer than sizeof(T) bytes remain.
    template <class T>
    bool read(T& value)
    {
        if (remaining() < sizeof(T))
            return false;
        value = decodeScalar<T>(m_data.data() + m_pos, m_order);
        m_pos += sizeof(T);
        return true;
    }

    /// Skips `count` bytes; false (nothing consumed) when fewer remain.
    bool skip(std::size_t count)
    {
        if (remaining() < count)
            return false;
        m_pos += count;
        return true;
    }

private:
    std::string_view m_data;
    std::size_t m_pos;
    std::endian m_order;
};

} // namespace trimlab
