#include "render/mfr/f2b_peeling.h"

namespace trimlab::render {

F2BPeeling::F2BPeeling(GlFunctions& gl) : m_state(gl, false), m_passes(gl)
{
}

void F2BPeeling::render(TrimFrame& frame)
{
    m_stats = m_passes.render(frame, m_state, {"peel_f2b", "peel_f2b_walk"});
}

std::optional<std::size_t> F2BPeeling::estimateBytes(int width, int height, const MethodParameters&) const
{
    return std::size_t(width) * std::size_t(height) * PeelingState::bytesPerPixel(false);
}

} // namespace trimlab::render
