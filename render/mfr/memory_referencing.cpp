#include "render/mfr/memory_referencing.h"

#include "render/gl/gl_error.h"
#include "render/gl/shader_library.h"
#include "render/frame/gpu_scene.h"
#include "render/frame/frame_counters.h"
#include "render/gl/bindings.h"
#include "render/mfr/head_image.h"
#include "render/mfr/method_parameter_table.h"
#include "render/mfr/pixel_state.h"
#include "render/mfr/trim_frame.h"
#include "render/mfr/trim_pass_state.h"

#include <stdexcept>
#include <string>

namespace trimlab::render {

MemoryReferencing::MemoryReferencing(GlFunctions& gl) : m_gl(gl)
{
}

void MemoryReferencing::countPass(TrimFrame& frame, PixelState& state)
{
    const GLuint program = trimProgram(frame, QStringLiteral("fragment_count"));
    m_gl.glUseProgram(program);
    setClipUniforms(frame, program);
    state.bind();
    frame.counters.bind();
    beginCapturePass(frame);
    frame.scene.draw(program, frame.projection);
    endCapturePass(frame);
    m_gl.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_ATOMIC_COUNTER_BARRIER_BIT);
}

void MemoryReferencing::allocateCounters(int sharedCounters)
{
    requireParameterValue(method_parameters::kSharedCounters, sharedCounters);
    if (sharedCounters == m_sharedCounters)
        return;
    m_sharedCounters = 0;
    m_counterBytes = (2 * std::size_t(sharedCounters) + 1) * sizeof(GLuint); // C, Cpr, total
    m_counters = GlBuffer(m_gl);
    m_gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m_counters.id());
    m_gl.glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(m_counterBytes), nullptr, GL_DYNAMIC_READ);
    checkAllocation(m_gl, "S-buffer shared counters", double(m_counterBytes));
    m_sharedCounters = sharedCounters;
}

GLuint MemoryReferencing::useReferencingProgram(TrimFrame& frame, const char* name, std::uint32_t regionLimit)
{
    const GLuint program = trimProgram(frame, QString::fromLatin1(name));
    m_gl.glUseProgram(program);
    m_gl.glUniform1ui(m_gl.glGetUniformLocation(program, "u_sharedCounterCount"), GLuint(m_sharedCounters));
    m_gl.glUniform2i(m_gl.glGetUniformLocation(program, "u_size"), frame.width, frame.height);
    m_gl.glUniform1ui(m_gl.glGetUniformLocation(program, "u_regionLimit"), regionLimit);
    return program;
}

std::uint64_t MemoryReferencing::reference(TrimFrame& frame, PixelState& state, HeadImage& head, int sharedCounters,
                                           std::uint32_t regionLimit)
{
    allocateCounters(sharedCounters);
    const GLuint zero = 0;
    m_gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m_counters.id());
    m_gl.glClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kSharedCountersStorage, m_counters.id());
    state.bind();
    head.bind();
    const GLuint groupsX = GLuint((frame.width + 15) / 16);
    const GLuint groupsY = GLuint((frame.height + 15) / 16);

    useReferencingProgram(frame, "sbuffer_address", regionLimit); // equation 5.1
    m_gl.glDispatchCompute(groupsX, groupsY, 1);
    m_gl.glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    useReferencingProgram(frame, "sbuffer_prefix", regionLimit); // Cpr and the total
    m_gl.glDispatchCompute(1, 1, 1);
    m_gl.glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    useReferencingProgram(frame, "sbuffer_offset", regionLimit); // equation 5.2
    m_gl.glDispatchCompute(groupsX, groupsY, 1);
    m_gl.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);

    // CPU-GPU synchronisation: glGetBufferSubData waits until the passes above are done.
    GLuint total = 0;
    m_gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m_counters.id());
    m_gl.glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, GLintptr(2 * std::size_t(m_sharedCounters) * sizeof(GLuint)),
                            sizeof(GLuint), &total);
    return total;
}

} // namespace trimlab::render
