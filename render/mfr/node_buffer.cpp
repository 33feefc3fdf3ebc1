#include "render/mfr/node_buffer.h"

#include "render/gl/gl_capabilities.h"
#include "render/gl/gl_error.h"

#include <algorithm>

namespace trimlab::render {

NodeBuffer::NodeBuffer(GlFunctions& gl, std::size_t bytesPerNode, std::string what)
    : m_gl(gl), m_bytesPerNode(bytesPerNode), m_what(std::move(what))
{
}

std::uint64_t NodeBuffer::maxNodes(const GlCapabilities& capabilities, std::size_t budgetBytes) const
{
    std::uint64_t bytes = std::uint64_t(std::max<qint64>(capabilities.maxShaderStorageBlockBytes, 0));
    if (budgetBytes > 0)
        bytes = std::min<std::uint64_t>(bytes, budgetBytes);
    return bytes / m_bytesPerNode;
}

void NodeBuffer::reserve(std::uint64_t nodes, const GlCapabilities& capabilities, int width, int height,
                         std::size_t budgetBytes)
{
    if (nodes > m_capacity || !m_buffer)
        reallocate(nodes, capabilities, width, height, budgetBytes);
}

void NodeBuffer::reallocate(std::uint64_t nodes, const GlCapabilities& capabilities, int width, int height,
                            std::size_t budgetBytes)
{
    const std::uint64_t limit = maxNodes(capabilities, budgetBytes);
    const double bytes = double(std::max<std::uint64_t>(nodes, 1)) * double(m_bytesPerNode);
    const bool budgetBinds = budgetBytes > 0 && limit < maxNodes(capabilities);
    const std::string needs =
        "The " + m_what + " needs " + std::to_string(nodes) + " fragments (" + megabytesText(bytes) + ")" +
        (width > 0 ? " at " + std::to_string(width) + "x" + std::to_string(height) : std::string());
    if (nodes > limit && budgetBinds)
        throw GpuMemoryError(needs + ", above the GPU memory budget of " + megabytesText(double(budgetBytes)) +
                             ". Raise the budget, lower the image size or pick a bounded method (k+-buffer, K+B-SB, "
                             "AB_FP).");
    if (nodes > limit)
        throw GpuMemoryError(needs + ", above this driver's " +
                             megabytesText(double(capabilities.maxShaderStorageBlockBytes)) +
                             " limit for one shader storage buffer (GL_MAX_SHADER_STORAGE_BLOCK_SIZE). Lower the "
                             "image size or pick a bounded method (k+-buffer, K+B-SB, AB_FP).");
    m_capacity = 0;
    m_buffer = GlBuffer(m_gl);
    m_gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m_buffer.id());
    m_gl.glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(bytes), nullptr, GL_DYNAMIC_COPY);
    checkAllocation(m_gl, m_what.c_str(), bytes);
    m_capacity = std::max<std::uint64_t>(nodes, 1);
}

void NodeBuffer::bind(GLuint binding, std::uint64_t nodes)
{
    const std::uint64_t bound = std::clamp<std::uint64_t>(nodes, 1, m_capacity);
    m_gl.glBindBufferRange(GL_SHADER_STORAGE_BUFFER, binding, m_buffer.id(), 0, GLsizeiptr(bound * m_bytesPerNode));
}

} // namespace trimlab::render
