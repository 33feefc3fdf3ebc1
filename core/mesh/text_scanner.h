#pragma once
/// \file
/// Line and token scanning for the text mesh formats (OBJ, OFF, ASCII PLY and STL), with
/// strict number parsing. Nothing here allocates per line or per token.

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace trimlab {

/// Splits text into lines terminated by "\n", "\r\n" or "\r" (the last line may lack a
/// terminator). Lines are numbered from 1.
class LineScanner {
public:
    explicit LineScanner(std::string_view text) : m_text(text) {}

    /// The next line without its terminator; false at the end of the text.
    bool next(std::string_view& line);
    /// 1-based number of the line `next` returned last (0 before the first call).
    [[nodiscard]] std::size_t lineNumber() const { return m_line; }
    /// Byte offset of the first byte not yet returned.
    [[nodiscard]] std::size_t offset() const { return m_pos; }
    [[nodiscard]] std::size_t bytesRemaining() const { return m_text.size() - m_pos; }

private:
    std::string_view m_text;
    std::size_t m_pos = 0;
    std::size_t m_line = 0;
};

/// A stream of whitespace-separated tokens over a whole text, tracking the line each
/// token is on (for error messages). No comment handling.
class TokenStream {
public:
    explicit TokenStream(std::string_view text, std::size_t firstLine = 1) : m_text(text), m_line(firstLine) {}

    /// The next token; false at the end of the text.
    bool next(std::string_view& token);
    /// 1-based line of the token `next` returned last (of the end, after the end).
    [[nodiscard]] std::size_t line() const { return m_tokenLine; }
    [[nodiscard]] std::size_t bytesRemaining() const { return m_text.size() - m_pos; }

private:
    std::string_view m_text;
    std::size_t m_pos = 0;
    std::size_t m_line = 1;
    std::size_t m_tokenLine = 1;
};

/// Removes the first token of `rest` (space/tab/vertical-tab/form-feed separated) and
/// returns it in `token`; false when `rest` holds no more tokens.
bool nextToken(std::string_view& rest, std::string_view& token);

/// `text` without a leading UTF-8 byte order mark (EF BB BF), which some editors write.
[[nodiscard]] std::string_view withoutUtf8Bom(std::string_view text);

/// `line` up to (not including) its first '#'.
[[nodiscard]] std::string_view stripComment(std::string_view line);

/// Parses a whole token as a decimal floating-point number: "1", "-2.5e3", "+4", and
/// "nan"/"inf" (which callers reject with a precise message). False for anything else,
/// including trailing characters ("1.5x") and empty tokens.
bool parseDouble(std::string_view token, double& value);

/// Parses a whole token as a decimal integer with optional sign; false for anything else
/// and for values outside int64.
bool parseInteger(std::string_view token, std::int64_t& value);

} // namespace trimlab
