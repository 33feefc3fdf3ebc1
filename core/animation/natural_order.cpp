#include "core/animation/natural_order.h"

#include <cctype>

namespace trimlab {

namespace {

bool isDigit(char c)
{
    return c >= '0' && c <= '9';
}

std::string_view digitRun(std::string_view text, std::size_t begin)
{
    std::size_t end = begin;
    while (end < text.size() && isDigit(text[end]))
        ++end;
    return text.substr(begin, end - begin);
}

std::string_view withoutLeadingZeros(std::string_view digits)
{
    const std::size_t first = digits.find_first_not_of('0');
    return first == std::string_view::npos ? std::string_view() : digits.substr(first);
}

// <0, 0, >0 like strcmp: numeric value first; equal values compare as equal here.
int compareNumbers(std::string_view a, std::string_view b)
{
    const std::string_view x = withoutLeadingZeros(a);
    const std::string_view y = withoutLeadingZeros(b);
    if (x.size() != y.size())
        return x.size() < y.size() ? -1 : 1;
    return x.compare(y);
}

// Compares ignoring case and treating equal-valued digit runs as equal; reports through
// `zeroTie` the first difference in leading zeros (negative: a has fewer).
int compareNatural(std::string_view a, std::string_view b, int& zeroTie)
{
    std::size_t i = 0;
    std::size_t j = 0;
    while (i < a.size() && j < b.size()) {
        if (isDigit(a[i]) && isDigit(b[j])) {
            const std::string_view x = digitRun(a, i);
            const std::string_view y = digitRun(b, j);
            if (const int c = compareNumbers(x, y); c != 0)
                return c;
            if (zeroTie == 0 && x.size() != y.size())
                zeroTie = x.size() < y.size() ? -1 : 1;
            i += x.size();
            j += y.size();
            continue;
        }
        const int ca = std::tolower(static_cast<unsigned char>(a[i]));
        const int cb = std::tolower(static_cast<unsigned char>(b[j]));
        if (ca != cb)
            return ca < cb ? -1 : 1;
        ++i;
        ++j;
    }
    if (i < a.size() || j < b.size())
        return i < a.size() ? 1 : -1;
    return 0;
}

} // namespace

bool naturalLess(std::string_view a, std::string_view b)
{
    int zeroTie = 0;
    if (const int c = compareNatural(a, b, zeroTie); c != 0)
        return c < 0;
    if (zeroTie != 0)
        return zeroTie < 0;
    return a < b;
}

} // namespace trimlab
