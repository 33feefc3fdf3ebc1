#pragma once
/// \file
/// Base64 (RFC 4648, standard alphabet, '=' padding) for the binary payloads of project
/// files. Decoding is strict so that a damaged payload is reported rather than guessed at.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace trimlab::timeline {

/// Encodes `bytes`; the result has 4·⌈n/3⌉ characters.
[[nodiscard]] std::string base64Encode(std::span<const std::uint8_t> bytes);

/// Decodes canonical base64. Throws std::invalid_argument with the reason ("character
/// '#' at offset 17 is not base64", "length 10 is not a multiple of 4", "padding inside
/// the data", "non-zero bits after the last byte") for anything else; whitespace is not
/// accepted either.
[[nodiscard]] std::vector<std::uint8_t> base64Decode(std::string_view text);

} // namespace trimlab::timeline
