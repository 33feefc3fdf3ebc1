#pragma once
/// \file
/// Writing a generated test mesh as a file, for tests that open meshes the way a user
/// does (through the GUI or the command line) rather than handing them over in memory.

#include "core/mesh/triangle_mesh.h"

#include <QString>

namespace trimlab::test {

/// Writes `mesh` to `path` as a plain Wavefront OBJ: one "v x y z" line per vertex with 9
/// significant digits (a float round-trips exactly), then one 1-based "f a b c" line per
/// triangle; no normals, texture coordinates or groups. Returns false when the file cannot
/// be written.
[[nodiscard]] bool writePlainObj(const TriangleMesh& mesh, const QString& path);

} // namespace trimlab::test
