#include "render/frame/subdivision_stencils.h"

#include "core/surface/subdivision_surface.h"

namespace trimlab::render {

SubdivisionStencils subdivisionStencils(const SubdivisionSurface& surface)
{
    SubdivisionStencils stencils;
    stencils.cageVertexCount = surface.cageVertexCount();
    const std::size_t outputs = surface.positions().size();
    stencils.sizes.reserve(outputs);
    stencils.offsets.reserve(outputs);
    for (std::size_t v = 0; v < outputs; ++v) {
        const std::span<const StencilWeight> row = surface.positionStencil(std::uint32_t(v));
        stencils.offsets.push_back(int(stencils.indices.size()));
        stencils.sizes.push_back(int(row.size()));
        for (const StencilWeight& w : row) {
            stencils.indices.push_back(int(w.cageVertex));
            stencils.weights.push_back(float(w.weight));
        }
    }
    stencils.triangles = surface.mesh().triangles;
    return stencils;
}

} // namespace trimlab::render
