#include "core/util/printable_text.h"

#include <cstdint>

namespace trimlab {

namespace {

constexpr char kHex[] = "0123456789abcdef";

void appendByteEscape(std::string& out, std::uint8_t byte)
{
    switch (byte) {
    case '\r':
        out += "\\r";
        return;
    case '\v':
        out += "\\v";
        return;
    case '\f':
        out += "\\f";
        return;
    default:
        out += "\\x";
        out += kHex[byte >> 4];
        out += kHex[byte & 0xf];
    }
}

void appendCodePointEscape(std::string& out, char32_t c)
{
    out += "\\u";
    for (int shift = 12; shift >= 0; shift -= 4)
        out += kHex[(c >> shift) & 0xf];
}

/// The length of the well-formed UTF-8 sequence at the start of `text` and its code point
/// (RFC 3629: no overlong forms, no surrogates, nothing above U+10FFFF); 0 when the bytes
/// there are not one.
std::size_t decodeOne(std::string_view text, char32_t& c)
{
    const auto byte = [&](std::size_t i) { return std::uint8_t(text[i]); };
    const std::uint8_t lead = byte(0);
    std::size_t length = 0;
    if (lead >= 0xc2 && lead <= 0xdf) {
        length = 2;
        c = lead & 0x1f;
    } else if (lead >= 0xe0 && lead <= 0xef) {
        length = 3;
        c = lead & 0x0f;
    } else if (lead >= 0xf0 && lead <= 0xf4) {
        length = 4;
        c = lead & 0x07;
    } else {
        return 0;
    }
    if (text.size() < length)
        return 0;
    for (std::size_t i = 1; i < length; ++i) {
        if ((byte(i) & 0xc0) != 0x80)
            return 0;
        c = (c << 6) | (byte(i) & 0x3f);
    }
    const char32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
    if (c < smallest[length] || c > 0x10ffff || (c >= 0xd800 && c <= 0xdfff))
        return 0;
    return length;
}

bool isHiddenCodePoint(char32_t c)
{
    return (c >= 0x80 && c <= 0x9f) || (c >= 0x202a && c <= 0x202e) || (c >= 0x2066 && c <= 0x2069);
}

} // namespace

std::string printableText(std::string_view utf8)
{
    std::string out;
    out.reserve(utf8.size());
    std::size_t i = 0;
    while (i < utf8.size()) {
        const auto byte = std::uint8_t(utf8[i]);
        if (byte < 0x80) {
            if ((byte < 0x20 && byte != '\n' && byte != '\t') || byte == 0x7f)
                appendByteEscape(out, byte);
            else
                out += char(byte);
            ++i;
            continue;
        }
        char32_t c = 0;
        const std::size_t length = decodeOne(utf8.substr(i), c);
        if (length == 0) {
            appendByteEscape(out, byte);
            ++i;
        } else if (isHiddenCodePoint(c)) {
            appendCodePointEscape(out, c);
            i += length;
        } else {
            out.append(utf8.substr(i, length));
            i += length;
        }
    }
    return out;
}

} // namespace trimlab
