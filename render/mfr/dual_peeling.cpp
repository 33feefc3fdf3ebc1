#include "render/mfr/dual_peeling.h"

namespace trimlab::render {

DualPeeling::DualPeeling(GlFunctions& gl) : m_state(gl, true), m_passes(gl)
{
}

void DualPeeling::render(TrimFrame& frame)
{
    m_stats = m_passes.render(frame, m_state, {"peel_dual", "peel_dual_walk"});
}

std::optional<std::size_t> DualPeeling::estimateBytes(int width, int height, const MethodParameters&) const
{
    return std::size_t(width) * std::size_t(height) * PeelingState::bytesPerPixel(true);
}

} // namespace trimlab::render
