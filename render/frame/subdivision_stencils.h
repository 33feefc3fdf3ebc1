#pragma once
/// \file
/// What evaluating a SubdivisionSurface (core/surface/subdivision_surface.h) on the GPU
/// needs, copied out of it once: the position stencils the CPU applies — the same weights
/// over the same cage vertices, rounded to float — in OpenSubdiv's compressed layout
/// (Far::StencilTable: per output vertex a size and an offset into control indices and
/// weights), and the fixed output triangles for the normals. Immutable and shareable, so
/// the viewport keeps it on the CPU and builds the GPU objects (gpu_subdivision.h) again in
/// a new context.
///
/// Limit mode's tangent stencils are not copied: the viewport's normals are the mesh's
/// angle-weighted vertex normals in both modes (GpuScene::updatePositions computes those
/// for the CPU's positions, gpu_vertex_normals.h for the GPU's).

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace trimlab {
class SubdivisionSurface;
}

namespace trimlab::render {

struct SubdivisionStencils {
    std::size_t cageVertexCount = 0;   ///< #C, the control points an evaluation takes
    std::vector<int> sizes;            ///< #V_out: entries of each output vertex's stencil
    std::vector<int> offsets;          ///< #V_out: its first entry
    std::vector<int> indices;          ///< Σ sizes cage vertices (< #C)
    std::vector<float> weights;        ///< Σ sizes weights
    std::vector<glm::uvec3> triangles; ///< the surface's fixed triangles (indices < #V_out)

    [[nodiscard]] std::size_t outputVertexCount() const { return sizes.size(); }
};

/// The stencils of `surface`'s output positions (SubdivisionSurface::positionStencil of
/// every output vertex) and its mesh's triangles.
[[nodiscard]] SubdivisionStencils subdivisionStencils(const SubdivisionSurface& surface);

} // namespace trimlab::render
