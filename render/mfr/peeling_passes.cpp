#include "render/mfr/peeling_passes.h"

#include "render/frame/frame_counters.h"
#include "render/gl/shader_library.h"
#include "render/frame/gpu_scene.h"
#include "render/mfr/peeling_state.h"
#include "render/mfr/trim_frame.h"
#include "render/mfr/trim_pass_state.h"
#include "render/frame/render_target.h"

#include <stdexcept>
#include <string>

namespace trimlab::render {

namespace {

// The CPU reads the query of the iteration this many before the one just issued: the GPU
// can run ahead, and at most this many skipped iterations are issued after the last.
constexpr int kQueryLag = 2;
constexpr int kClearPasses = 2; // PixelState and the peeling cursor

void setFirstPass(GlFunctions& gl, GLuint program, bool first)
{
    gl.glUniform1i(gl.glGetUniformLocation(program, "u_firstPass"), first ? 1 : 0);
}

} // namespace

PeelingPasses::PeelingPasses(GlFunctions& gl) : m_gl(gl)
{
}

MethodStats PeelingPasses::render(TrimFrame& frame, PeelingState& state, const PeelingPrograms& programs)
{
    if (frame.parameters.maxPeelingPasses < 1)
        throw std::invalid_argument("the peeling pass bound must be at least 1 (got " +
                                    std::to_string(frame.parameters.maxPeelingPasses) + ").");
    state.allocate(frame.width, frame.height);
    state.clear(frame.shaders);
    const int issued = peel(frame, state, programs);
    resolvePass(frame, state);
    const int passes = executedPasses(issued);
    return {passes, passes + kClearPasses + 1, state.memoryBytes(), false};
}

int PeelingPasses::peel(TrimFrame& frame, PeelingState& state, const PeelingPrograms& programs)
{
    const GLuint geometry = trimProgram(frame, QString::fromLatin1(programs.geometry));
    const GLuint walk = trimProgram(frame, QString::fromLatin1(programs.walk));
    int issued = 0;
    for (int iteration = 0; iteration < frame.parameters.maxPeelingPasses; ++iteration) {
        const bool first = iteration == 0;
        const GLuint walkQuery = query(iteration);
        if (!first)
            m_gl.glBeginConditionalRender(query(iteration - 1), GL_QUERY_WAIT);
        geometryPass(frame, state, geometry, first);
        walkPass(frame, state, walk, first, walkQuery);
        if (!first)
            m_gl.glEndConditionalRender();
        ++issued;
        if (iteration >= kQueryLag && !queryResult(iteration - kQueryLag))
            break;
    }
    return issued;
}

void PeelingPasses::geometryPass(TrimFrame& frame, PeelingState& state, GLuint program, bool first)
{
    m_gl.glUseProgram(program);
    setClipUniforms(frame, program);
    setFirstPass(m_gl, program, first);
    state.bind();
    frame.counters.bind();
    beginCapturePass(frame);
    frame.scene.draw(program, frame.projection);
    endCapturePass(frame);
    m_gl.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void PeelingPasses::walkPass(TrimFrame& frame, PeelingState& state, GLuint program, bool first, GLuint query)
{
    m_gl.glUseProgram(program);
    setTrimWalkUniforms(frame, program);
    setFirstPass(m_gl, program, first);
    state.bind();
    frame.counters.bind();
    beginCapturePass(frame); // depth test off: every pixel still peeling passes
    m_gl.glBeginQuery(GL_ANY_SAMPLES_PASSED, query);
    frame.target.drawFullscreenTriangle();
    m_gl.glEndQuery(GL_ANY_SAMPLES_PASSED);
    endCapturePass(frame);
    m_gl.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void PeelingPasses::resolvePass(TrimFrame& frame, PeelingState& state)
{
    const GLuint program = trimProgram(frame, QStringLiteral("peeling_resolve"));
    m_gl.glUseProgram(program);
    setTrimWalkUniforms(frame, program); // the rule and the clip / cap uniforms of CAPPING
    setOutputUniforms(frame, program);
    state.bind();
    frame.counters.bind();
    drawResolvePass(frame, program);
    m_gl.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_ATOMIC_COUNTER_BARRIER_BIT);
}

int PeelingPasses::executedPasses(int issued)
{
    // Iteration i > 0 ran exactly when the walk pass before it let a pixel pass.
    int passes = issued > 0 ? 1 : 0;
    for (int iteration = 1; iteration < issued; ++iteration)
        passes += queryResult(iteration - 1) ? 1 : 0;
    return passes;
}

GLuint PeelingPasses::query(int iteration)
{
    while (int(m_queries.size()) <= iteration)
        m_queries.emplace_back(m_gl);
    return m_queries[std::size_t(iteration)].id();
}

bool PeelingPasses::queryResult(int iteration)
{
    GLuint anyPassed = 0;
    m_gl.glGetQueryObjectuiv(query(iteration), GL_QUERY_RESULT, &anyPassed);
    return anyPassed != 0;
}

} // namespace trimlab::render
