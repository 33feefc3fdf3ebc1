#include "core/timeline/base64.h"

#include <array>
#include <stdexcept>

namespace trimlab::timeline {

namespace {

constexpr std::string_view kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

constexpr std::array<std::int8_t, 256> decodeTable()
{
    std::array<std::int8_t, 256> table{};
    table.fill(-1);
    for (std::size_t i = 0; i < kAlphabet.size(); ++i)
        table[static_cast<unsigned char>(kAlphabet[i])] = static_cast<std::int8_t>(i);
    return table;
}

constexpr std::array<std::int8_t, 256> kDecode = decodeTable();

std::string characterText(char c)
{
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f)
        return std::string("'") + c + "'";
    return "byte " + std::to_string(unsigned(u));
}

// Number of '=' at the end (0, 1 or 2); more is an error.
std::size_t paddingLength(std::string_view text)
{
    std::size_t padding = 0;
    while (padding < text.size() && text[text.size() - 1 - padding] == '=')
        ++padding;
    if (padding > 2)
        throw std::invalid_argument("too much '=' padding at the end");
    return padding;
}

} // namespace

std::string base64Encode(std::span<const std::uint8_t> bytes)
{
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 3 <= bytes.size(); i += 3) {
        const std::uint32_t v = (std::uint32_t(bytes[i]) << 16) | (std::uint32_t(bytes[i + 1]) << 8) | bytes[i + 2];
        out += kAlphabet[(v >> 18) & 63];
        out += kAlphabet[(v >> 12) & 63];
        out += kAlphabet[(v >> 6) & 63];
        out += kAlphabet[v & 63];
    }
    const std::size_t rest = bytes.size() - i;
    if (rest > 0) {
        const std::uint32_t v = (std::uint32_t(bytes[i]) << 16) | (rest == 2 ? std::uint32_t(bytes[i + 1]) << 8 : 0u);
        out += kAlphabet[(v >> 18) & 63];
        out += kAlphabet[(v >> 12) & 63];
        out += rest == 2 ? kAlphabet[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

std::vector<std::uint8_t> base64Decode(std::string_view text)
{
    if (text.size() % 4 != 0)
        throw std::invalid_argument("length " + std::to_string(text.size()) + " is not a multiple of 4");
    const std::size_t padding = paddingLength(text);
    const std::size_t symbols = text.size() - padding;
    std::vector<std::uint8_t> out;
    out.reserve(text.size() / 4 * 3);
    std::uint32_t accumulator = 0;
    int bits = 0;
    for (std::size_t i = 0; i < symbols; ++i) {
        const std::int8_t value = kDecode[static_cast<unsigned char>(text[i])];
        if (value < 0)
            throw std::invalid_argument(text[i] == '=' ? "padding '=' inside the data at offset " + std::to_string(i)
                                                       : "character " + characterText(text[i]) + " at offset " +
                                                             std::to_string(i) + " is not base64");
        accumulator = (accumulator << 6) | std::uint32_t(value);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out.push_back(std::uint8_t((accumulator >> bits) & 0xff));
        }
    }
    // Canonical encodings leave the bits below the last whole byte zero; anything else
    // means the final character was altered.
    if ((accumulator & ((1u << bits) - 1)) != 0)
        throw std::invalid_argument("non-zero bits after the last byte (the final character was altered)");
    return out;
}

} // namespace trimlab::timeline
