#pragma once
/// \file
/// What every Wavefront OBJ reader here shares (the mesh reader, obj_reader.h, and the
/// subdivision-cage reader, surface/cage_obj.h): the file's name and current line for
/// errors, and the `v` and `f` lines, so both accept and refuse exactly the same vertex
/// and face syntax with the same words.

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace trimlab {

class ObjLineParser {
public:
    explicit ObjLineParser(const std::string& displayName) : m_name(displayName) {}

    /// The line being parsed (1-based), for errors.
    void setLine(std::size_t lineNumber) { m_line = lineNumber; }
    [[nodiscard]] std::size_t line() const { return m_line; }
    [[nodiscard]] const std::string& name() const { return m_name; }

    /// Throws MeshLoadError "NAME:LINE: reason".
    [[noreturn]] void fail(const std::string& reason) const;

    /// The coordinates of a `v x y z [w]` line (`rest`: after the keyword); `vertexCount`
    /// vertices are defined before it. Fails for fewer than 3 numbers, a non-number, a
    /// value that is not finite as a float, or more than kMaxMeshVertices vertices.
    [[nodiscard]] glm::dvec3 parseVertexLine(std::string_view rest, std::size_t vertexCount) const;

    /// Appends the 0-based vertex of each corner of an `f c1 c2 c3 ...` line to `indices`
    /// (corners "v", "v/vt", "v//vn", "v/vt/vn"; negative v counts back from the last
    /// vertex defined before the line) and returns how many. Fails for index 0, a
    /// backward index before the first vertex, an index beyond kMaxMeshVertices, a
    /// malformed corner, or fewer than 3 corners. Forward indices are range-checked by
    /// the caller at the end: a face may name vertices defined after it.
    std::uint32_t parseFaceLine(std::string_view rest, std::size_t vertexCount,
                                std::vector<std::uint32_t>& indices) const;

private:
    [[nodiscard]] std::uint32_t parseCorner(std::string_view corner, std::size_t vertexCount) const;

    const std::string& m_name;
    std::size_t m_line = 0;
};

} // namespace trimlab
