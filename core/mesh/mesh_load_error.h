#pragma once
/// \file
/// The typed exception every mesh loader throws: which file, where in it, and why.

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>

namespace trimlab {

/// Where in a file a load error was found. Both parts are optional:
/// - `line`: 1-based line of a text file; 0 means "no line".
/// - `element`: a description such as "face 17", "vertex 3", "accessor 3" or
///   "byte offset 1234"; empty means "the file as a whole".
struct MeshErrorLocation {
    std::size_t line = 0;
    std::string element;
};

/// A mesh file could not be loaded. `what()` reads `FILE[:LINE]: [ELEMENT: ]REASON`, e.g.
/// `cube.obj:12: face references vertex 9, but the file has only 8 vertices` or
/// `mesh.ply: face 3: index -1 is negative`. The reason says what is wrong and, where it
/// helps, what to do about it. Thrown for every problem caused by file contents; never
/// for programmer errors.
class MeshLoadError : public std::runtime_error {
public:
    /// `file` is the display name (usually the path as the user gave it).
    MeshLoadError(std::string file, std::string reason, MeshErrorLocation where = {});

    [[nodiscard]] const std::string& file() const noexcept { return m_file; }
    /// The 1-based line, or nullopt when the error is not tied to a line.
    [[nodiscard]] std::optional<std::size_t> line() const noexcept;
    /// The element description ("face 17"), or "" when there is none.
    [[nodiscard]] const std::string& element() const noexcept { return m_where.element; }
    [[nodiscard]] const std::string& reason() const noexcept { return m_reason; }

private:
    std::string m_file;
    std::string m_reason;
    MeshErrorLocation m_where;
};

} // namespace trimlab
