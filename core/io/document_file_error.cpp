#include "core/io/document_file_error.h"

namespace trimlab::io {

namespace {

std::string message(const std::string& file, const std::string& where, const std::string& reason)
{
    return file + ": " + (where.empty() ? std::string() : where + ": ") + reason;
}

} // namespace

DocumentFileError::DocumentFileError(std::string file, std::string where, std::string reason)
    : std::runtime_error(message(file, where, reason)),
      m_file(std::move(file)),
      m_where(std::move(where)),
      m_reason(std::move(reason))
{
}

} // namespace trimlab::io
