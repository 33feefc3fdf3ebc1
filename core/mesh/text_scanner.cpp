#include "core/mesh/text_scanner.h"

#include <charconv>
#include <cstdlib>
#include <string>

namespace trimlab {

namespace {

bool isBlank(char c)
{
    return c == ' ' || c == '\t' || c == '\v' || c == '\f';
}

bool isSpaceOrNewline(char c)
{
    return isBlank(c) || c == '\n' || c == '\r';
}

// from_chars rejects a leading '+', which some writers emit.
std::string_view withoutPlus(std::string_view token)
{
    if (token.size() > 1 && token.front() == '+' && token[1] != '-' && token[1] != '+')
        token.remove_prefix(1);
    return token;
}

} // namespace

bool LineScanner::next(std::string_view& line)
{
    if (m_pos >= m_text.size())
        return false;
    std::size_t end = m_pos;
    while (end < m_text.size() && m_text[end] != '\n' && m_text[end] != '\r')
        ++end;
    line = m_text.substr(m_pos, end - m_pos);
    if (end < m_text.size()) {
        if (m_text[end] == '\r' && end + 1 < m_text.size() && m_text[end + 1] == '\n')
            ++end;
        ++end;
    }
    m_pos = end;
    ++m_line;
    return true;
}

bool TokenStream::next(std::string_view& token)
{
    while (m_pos < m_text.size() && isSpaceOrNewline(m_text[m_pos])) {
        const char c = m_text[m_pos++];
        if (c == '\n' || (c == '\r' && (m_pos >= m_text.size() || m_text[m_pos] != '\n')))
            ++m_line;
    }
    m_tokenLine = m_line;
    if (m_pos >= m_text.size())
        return false;
    const std::size_t start = m_pos;
    while (m_pos < m_text.size() && !isSpaceOrNewline(m_text[m_pos]))
        ++m_pos;
    token = m_text.substr(start, m_pos - start);
    return true;
}

bool nextToken(std::string_view& rest, std::string_view& token)
{
    std::size_t start = 0;
    while (start < rest.size() && isBlank(rest[start]))
        ++start;
    if (start == rest.size()) {
        rest = {};
        return false;
    }
    std::size_t end = start;
    while (end < rest.size() && !isBlank(rest[end]))
        ++end;
    token = rest.substr(start, end - start);
    rest.remove_prefix(end);
    return true;
}

std::string_view withoutUtf8Bom(std::string_view text)
{
    return text.substr(0, 3) == "\xEF\xBB\xBF" ? text.substr(3) : text;
}

std::string_view stripComment(std::string_view line)
{
    const std::size_t hash = line.find('#');
    return hash == std::string_view::npos ? line : line.substr(0, hash);
}

bool parseDouble(std::string_view token, double& value)
{
    token = withoutPlus(token);
    if (token.empty())
        return false;
    const char* end = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), end, value);
    // Out-of-range values (1e999, 1e-999) come back as result_out_of_range without a
    // value; strtod gives the conventional ±HUGE_VAL or the underflowed result, so that
    // callers report "non-finite" rather than "not a number". Rare, so the copy is fine.
    if (ec == std::errc::result_out_of_range && ptr == end) {
        const std::string copy(token);
        value = std::strtod(copy.c_str(), nullptr);
        return true;
    }
    return ec == std::errc() && ptr == end;
}

bool parseInteger(std::string_view token, std::int64_t& value)
{
    token = withoutPlus(token);
    if (token.empty())
        return false;
    const char* end = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), end, value);
    return ec == std::errc() && ptr == end;
}

} // namespace trimlab
