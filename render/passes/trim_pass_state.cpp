#include "passes/trim_pass_state.h"

#include "gpu_scene.h"
#include "mfr/trim_frame.h"
#include "render_target.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>

namespace trimlab::render {

void setClipUniforms(const TrimFrame& frame, GLuint program)
{
    // Planes transform with the inverse transpose.
    const glm::vec4 plane(glm::transpose(glm::inverse(frame.view)) * frame.settings.clip.equation());
    frame.gl.glUniform1i(frame.gl.glGetUniformLocation(program, "u_clipEnabled"), frame.settings.clip.enabled ? 1 : 0);
    frame.gl.glUniform4fv(frame.gl.glGetUniformLocation(program, "u_clipPlaneView"), 1, glm::value_ptr(plane));
    frame.gl.glUniform1f(frame.gl.glGetUniformLocation(program, "u_zNear"), float(frame.camera.zNear));
}

void setTrimWalkUniforms(const TrimFrame& frame, GLuint program)
{
    frame.gl.glUniform1i(frame.gl.glGetUniformLocation(program, "u_trimEnabled"), frame.settings.trimEnabled ? 1 : 0);
    frame.gl.glUniform1i(frame.gl.glGetUniformLocation(program, "u_rule"), static_cast<int>(frame.settings.rule));
    frame.gl.glUniform1i(frame.gl.glGetUniformLocation(program, "u_dynamicRule"), frame.dynamicRule);
    frame.gl.glUniform1i(frame.gl.glGetUniformLocation(program, "u_referenceIsBase"), frame.referenceIsBase ? 1 : 0);
}

void setOutputUniforms(const TrimFrame& frame, GLuint program)
{
    const double tanHalfY = std::tan(glm::radians(frame.camera.fovyDegrees) * 0.5);
    const double aspect = double(frame.width) / double(frame.height);
    const glm::mat4 projection(frame.projection);
    GlFunctions& gl = frame.gl;
    gl.glUniformMatrix4fv(gl.glGetUniformLocation(program, "u_projection"), 1, GL_FALSE, glm::value_ptr(projection));
    gl.glUniform2f(gl.glGetUniformLocation(program, "u_viewportSize"), float(frame.width), float(frame.height));
    gl.glUniform2f(gl.glGetUniformLocation(program, "u_tanHalfFov"), float(tanHalfY * aspect), float(tanHalfY));
    gl.glUniform1i(gl.glGetUniformLocation(program, "u_vertexColors"), frame.scene.hasVertexColors() ? 1 : 0);
    frame.scene.bindStorage();
}

void beginCapturePass(TrimFrame& frame)
{
    frame.target.bindForDrawing();
    frame.gl.glDisable(GL_DEPTH_TEST);
    frame.gl.glDisable(GL_CULL_FACE);
    frame.gl.glDisable(GL_BLEND);
    frame.gl.glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    frame.gl.glDepthMask(GL_FALSE);
}

void endCapturePass(TrimFrame& frame)
{
    frame.gl.glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    frame.gl.glDepthMask(GL_TRUE);
}

void drawResolvePass(TrimFrame& frame, GLuint program)
{
    frame.gl.glUseProgram(program);
    frame.target.bindForDrawing();
    frame.gl.glEnable(GL_DEPTH_TEST);
    frame.gl.glDepthFunc(GL_ALWAYS);
    frame.target.drawFullscreenTriangle();
    frame.gl.glDepthFunc(GL_LESS);
}

} // namespace trimlab::render
