#pragma once
/// \file
/// The base of the typed exceptions TrimLab's JSON document loaders throw (projects,
/// skeletons, surfaces): which file, where in it, and why — so every loader words its
/// errors the same way and the GUI can show the three parts.

#include <stdexcept>
#include <string>

namespace trimlab::io {

/// A document could not be loaded. `what()` reads `FILE: [WHERE: ]REASON`, e.g.
/// `scene.trimlab: frames[3].after: CRC mismatch …`. Thrown for problems caused by file
/// contents or by reading the file; never for programmer errors.
class DocumentFileError : public std::runtime_error {
public:
    /// `where` is a JSON path such as "frames[3].after" or "" for the file as a whole.
    DocumentFileError(std::string file, std::string where, std::string reason);

    [[nodiscard]] const std::string& file() const noexcept { return m_file; }
    [[nodiscard]] const std::string& where() const noexcept { return m_where; }
    [[nodiscard]] const std::string& reason() const noexcept { return m_reason; }

private:
    std::string m_file;
    std::string m_where;
    std::string m_reason;
};

} // namespace trimlab::io
