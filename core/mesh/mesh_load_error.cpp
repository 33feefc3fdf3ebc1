#include "core/mesh/mesh_load_error.h"

namespace trimlab {

namespace {

std::string composeMessage(const std::string& file, const std::string& reason, const MeshErrorLocation& where)
{
    std::string text = file;
    if (where.line > 0)
        text += ':' + std::to_string(where.line);
    text += ": ";
    if (!where.element.empty())
        text += where.element + ": ";
    return text + reason;
}

} // namespace

MeshLoadError::MeshLoadError(std::string file, std::string reason, MeshErrorLocation where)
    : std::runtime_error(composeMessage(file, reason, where)),
      m_file(std::move(file)),
      m_reason(std::move(reason)),
      m_where(std::move(where))
{
}

std::optional<std::size_t> MeshLoadError::line() const noexcept
{
    if (m_where.line == 0)
        return std::nullopt;
    return m_where.line;
}

} // namespace trimlab
