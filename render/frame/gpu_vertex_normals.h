#pragma once
/// \file
/// Recomputes one object's vertex normals on the GPU from the positions in a GpuScene,
/// after a compute pass moved them (frame/gpu_skinning.h), so that no pose has to come
/// back to the CPU for its normals. The normals are those of vertexNormals
/// (core/mesh/triangle_mesh.h): unit face normals weighted by the corner angle.
///
/// Float atomics are not in GL 4.3 core, and scattering from triangles would make the sum's
/// order depend on scheduling; instead each vertex gathers from its one-ring, stored once
/// as compressed rows (CSR: per vertex the corners of its triangles, in triangle order, the
/// CPU's summation order), so the result is deterministic.

#include "render/frame/gpu_scene.h"
#include "render/gl/gl_functions.h"
#include "render/gl/gl_objects.h"
#include "render/gl/shader_library.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace trimlab::render {

class GpuVertexNormals {
public:
    /// Uploads the one-ring of a mesh of `vertexCount` vertices and `triangles`
    /// (object-local indices, all < vertexCount). The context must be current. Throws
    /// GpuMemoryError, or std::invalid_argument for an index out of range.
    GpuVertexNormals(GlFunctions& gl, const std::vector<glm::uvec3>& triangles, std::size_t vertexCount);

    /// Writes the normals of `object` from its positions (both in the scene's buffers; the
    /// object must be the mesh given at construction — checked by its counts only). Issues
    /// no barrier for the positions: the caller orders this after the pass that wrote them.
    /// Throws std::invalid_argument when the counts differ.
    void recompute(ShaderLibrary& shaders, const GpuObjectGeometry& object);

    [[nodiscard]] std::size_t memoryBytes() const { return m_bytes; }

private:
    GlFunctions& m_gl;
    GlBuffer m_ring;
    std::size_t m_vertexCount = 0;
    std::size_t m_triangleCount = 0;
    std::size_t m_bytes = 0;
};

} // namespace trimlab::render
