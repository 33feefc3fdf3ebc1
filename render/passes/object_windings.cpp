#include "render/passes/object_windings.h"

#include "render/gl/bindings.h"

#include "core/trim/csg_expression.h"

#include <stdexcept>
#include <string>

namespace trimlab::render {

ObjectWindingBuffer::ObjectWindingBuffer(GlFunctions& gl) : m_gl(gl), m_buffer(gl)
{
}

std::size_t ObjectWindingBuffer::bytesFor(int width, int height, int objects)
{
    return std::size_t(width) * std::size_t(height) * std::size_t(objects) * sizeof(GLint);
}

void ObjectWindingBuffer::allocate(int width, int height, int objects)
{
    if (objects < 1 || objects > kMaxCsgOperands)
        throw std::invalid_argument("per-object winding indices are kept for 1 to " + std::to_string(kMaxCsgOperands) +
                                    " objects, not " + std::to_string(objects) + ".");
    if (width == m_width && height == m_height && objects == m_objects)
        return;
    m_width = m_height = m_objects = 0;
    const std::size_t bytes = bytesFor(width, height, objects);
    m_gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m_buffer.id());
    m_gl.glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(bytes), nullptr, GL_DYNAMIC_COPY);
    checkAllocation(m_gl, "per-object winding indices", double(bytes));
    m_width = width;
    m_height = height;
    m_objects = objects;
    m_bytes = bytes;
}

void ObjectWindingBuffer::clear()
{
    const GLuint zero = 0;
    m_gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m_buffer.id());
    m_gl.glClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    m_gl.glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void ObjectWindingBuffer::bind(GLuint program)
{
    m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kObjectWindingsStorage, m_buffer.id());
    m_gl.glUniform1ui(m_gl.glGetUniformLocation(program, "u_objectWindingWidth"), GLuint(m_width));
}

} // namespace trimlab::render
