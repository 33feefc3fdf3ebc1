#include "render/frame/vertex_dispatch.h"

#include <algorithm>

namespace trimlab::render {

void dispatchOverVertices(GlFunctions& gl, GLuint program, std::size_t vertexCount)
{
    constexpr std::size_t kMaxGroups = 65535; // GL_MAX_COMPUTE_WORK_GROUP_COUNT's guaranteed minimum
    const GLint firstVertex = gl.glGetUniformLocation(program, "u_firstVertex");
    for (std::size_t first = 0; first < vertexCount; first += kMaxGroups * kVertexGroupSize) {
        const std::size_t groups =
            std::min(kMaxGroups, (vertexCount - first + kVertexGroupSize - 1) / kVertexGroupSize);
        gl.glUniform1ui(firstVertex, GLuint(first));
        gl.glDispatchCompute(GLuint(groups), 1, 1);
    }
}

} // namespace trimlab::render
