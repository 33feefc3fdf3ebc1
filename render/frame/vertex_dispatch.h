#pragma once
/// \file
/// Runs a compute program with one invocation per vertex (local size 64, as the
/// per-vertex shaders declare), in as many dispatches as the driver's group-count limit
/// needs: GL 4.3 guarantees only 65535 groups per dimension, 4,194,240 vertices.

#include "render/gl/gl_functions.h"

#include <cstddef>

namespace trimlab::render {

/// The local size of every per-vertex compute shader (shaders/skinning.comp,
/// shaders/vertex_normals.comp).
inline constexpr std::size_t kVertexGroupSize = 64;

/// Dispatches `program` (in use) over `vertexCount` vertices; each dispatch sets the
/// program's `uniform uint u_firstVertex` to the first vertex it covers.
void dispatchOverVertices(GlFunctions& gl, GLuint program, std::size_t vertexCount);

} // namespace trimlab::render
