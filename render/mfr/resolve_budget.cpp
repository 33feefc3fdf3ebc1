#include "render/mfr/resolve_budget.h"

#include "render/gl/gl_capabilities.h"

#include <limits>

namespace trimlab::render {

int resolveLoopBudget(const GlCapabilities& capabilities)
{
    if (capabilities.renderer.contains(QLatin1String("llvmpipe")))
        return 50000;
    return std::numeric_limits<int>::max();
}

void setResolveLoopBudget(GlFunctions& gl, GLuint program, const GlCapabilities& capabilities)
{
    gl.glUniform1i(gl.glGetUniformLocation(program, "u_loopBudget"), resolveLoopBudget(capabilities));
}

} // namespace trimlab::render
