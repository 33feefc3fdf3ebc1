#include "mfr/node_buffer.h"

#include "gl/gl_capabilities.h"
#include "gl/gl_error.h"

#include <algorithm>
#include <cstdio>

namespace trimlab::render {

namespace {

std::string megabytes(double bytes)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.1f MB", bytes / (1024.0 * 1024.0));
    return text;
}

} // namespace

NodeBuffer::NodeBuffer(GlFunctions& gl, std::size_t bytesPerNode, std::string what)
    : m_gl(gl), m_bytesPerNode(bytesPerNode), m_what(std::move(what))
{
}

std::uint64_t NodeBuffer::maxNodes(const GlCapabilities& capabilities) const
{
    return std::uint64_t(std::max<qint64>(capabilities.maxShaderStorageBlockBytes, 0)) / m_bytesPerNode;
}

void NodeBuffer::reserve(std::uint64_t nodes, const GlCapabilities& capabilities, int width, int height)
{
    if (nodes > m_capacity || !m_buffer)
        reallocate(nodes, capabilities, width, height);
}

void NodeBuffer::reallocate(std::uint64_t nodes, const GlCapabilities& capabilities, int width, int height)
{
    const std::uint64_t limit = maxNodes(capabilities);
    const double bytes = double(std::max<std::uint64_t>(nodes, 1)) * double(m_bytesPerNode);
    if (nodes > limit)
        throw GpuMemoryError("The " + m_what + " needs " + std::to_string(nodes) + " fragments (" + megabytes(bytes) +
                             ")" + (width > 0 ? " at " + std::to_string(width) + "x" + std::to_string(height) : std::string()) +
                             ", above this driver's " +
                             megabytes(double(capabilities.maxShaderStorageBlockBytes)) +
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
