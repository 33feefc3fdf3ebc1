#include "render/frame/gpu_vertex_normals.h"

#include "render/frame/vertex_dispatch.h"
#include "render/gl/bindings.h"

#include <cstdint>
#include <stdexcept>
#include <string>

namespace trimlab::render {

namespace {

// The VertexRing layout of shaders/vertex_normals.comp: #V + 1 offsets, then the 3·#T
// corners (triangle·3 + corner) grouped by vertex in triangle order, then the triangles.
std::vector<std::uint32_t> vertexRing(const std::vector<glm::uvec3>& triangles, std::size_t vertexCount)
{
    const std::size_t cornersStart = vertexCount + 1;
    const std::size_t trianglesStart = cornersStart + 3 * triangles.size();
    std::vector<std::uint32_t> ring(trianglesStart + 3 * triangles.size(), 0u);
    for (const glm::uvec3& t : triangles)
        for (int i = 0; i < 3; ++i) {
            if (t[i] >= vertexCount)
                throw std::invalid_argument("GPU normals: a triangle names vertex " + std::to_string(t[i]) + " of " +
                                            std::to_string(vertexCount) + ".");
            ++ring[t[i] + 1];
        }
    for (std::size_t v = 0; v < vertexCount; ++v)
        ring[v + 1] += ring[v];
    std::vector<std::uint32_t> next(ring.begin(), ring.begin() + std::ptrdiff_t(vertexCount));
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (int i = 0; i < 3; ++i) {
            ring[cornersStart + next[triangles[t][i]]++] = std::uint32_t(3 * t + std::size_t(i));
            ring[trianglesStart + 3 * t + std::size_t(i)] = triangles[t][i];
        }
    return ring;
}

} // namespace

GpuVertexNormals::GpuVertexNormals(GlFunctions& gl, const std::vector<glm::uvec3>& triangles, std::size_t vertexCount)
    : m_gl(gl), m_ring(gl), m_vertexCount(vertexCount), m_triangleCount(triangles.size())
{
    const std::vector<std::uint32_t> ring = vertexRing(triangles, vertexCount);
    m_bytes = ring.size() * sizeof(std::uint32_t);
    m_gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m_ring.id());
    m_gl.glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(m_bytes), ring.data(), GL_STATIC_DRAW);
    checkAllocation(m_gl, "vertex one-rings", double(m_bytes));
}

void GpuVertexNormals::recompute(ShaderLibrary& shaders, const GpuObjectGeometry& object)
{
    if (object.vertexCount != m_vertexCount || object.triangleCount != m_triangleCount)
        throw std::invalid_argument("GPU normals: the object has " + std::to_string(object.vertexCount) +
                                    " vertices and " + std::to_string(object.triangleCount) +
                                    " triangles, the one-ring was built for " + std::to_string(m_vertexCount) +
                                    " and " + std::to_string(m_triangleCount) + ".");
    const GLuint program = shaders.program(QStringLiteral("vertex_normals"));
    m_gl.glUseProgram(program);
    m_gl.glUniform1ui(m_gl.glGetUniformLocation(program, "u_vertexCount"), GLuint(m_vertexCount));
    m_gl.glUniform1ui(m_gl.glGetUniformLocation(program, "u_baseVertex"), GLuint(object.baseVertex));
    m_gl.glUniform1ui(m_gl.glGetUniformLocation(program, "u_cornersStart"), GLuint(m_vertexCount + 1));
    m_gl.glUniform1ui(m_gl.glGetUniformLocation(program, "u_trianglesStart"),
                      GLuint(m_vertexCount + 1 + 3 * m_triangleCount));
    m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kScenePositionsStorage, object.positions);
    m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kSceneNormalsStorage, object.normals);
    m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kVertexRingStorage, m_ring.id());
    dispatchOverVertices(m_gl, program, m_vertexCount);
}

} // namespace trimlab::render
