#include "core/mesh/reader_support.h"

#include "core/mesh/mesh_load_error.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <sstream>

namespace trimlab {

std::size_t cappedReserve(std::uint64_t declared, std::size_t bytesRemaining, std::size_t minBytesPerItem)
{
    const std::uint64_t possible = bytesRemaining / std::max<std::size_t>(minBytesPerItem, 1) + 1;
    return static_cast<std::size_t>(std::min(declared, possible));
}

bool isFiniteFloat(double value)
{
    return std::isfinite(value) && std::fabs(value) <= static_cast<double>(FLT_MAX);
}

std::string describeNonFinite(double value)
{
    if (std::isnan(value))
        return "nan";
    if (std::isinf(value))
        return value > 0 ? "inf" : "-inf";
    std::ostringstream text;
    text << value << " (too large for a 32-bit float)";
    return text.str();
}

std::string nonFiniteCoordinateReason(double value)
{
    return "has a non-finite coordinate (" + describeNonFinite(value) + "); coordinates must be finite numbers";
}

std::string countNoun(std::uint64_t count, std::string_view singular, std::string_view plural)
{
    return std::to_string(count) + ' ' + std::string(count == 1 ? singular : plural);
}

std::string vertexCountPhrase(std::size_t vertexCount, bool zeroBased)
{
    if (vertexCount == 0)
        return "the file has no vertices";
    std::string text = "the file has only " + countNoun(vertexCount, "vertex", "vertices");
    if (zeroBased)
        text += " (numbered 0 to " + std::to_string(vertexCount - 1) + ")";
    return text;
}

void rejectBinaryData(std::string_view text, const std::string& displayName, std::string_view formatName)
{
    const std::size_t nul = text.find('\0');
    if (nul == std::string_view::npos)
        return;
    throw MeshLoadError(displayName, "binary data in a text format (a NUL byte at byte offset " + std::to_string(nul) +
                                         "); is this really an " + std::string(formatName) + " file?");
}

} // namespace trimlab
