#include "render/mfr/trim_pass_state.h"

#include "render/frame/gpu_scene.h"
#include "render/mfr/pixel_state.h"
#include "render/passes/object_windings.h"
#include "render/mfr/trim_frame.h"
#include "render/frame/render_target.h"

#include "core/trim/csg_expression.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace trimlab::render {

void setClipUniforms(const TrimFrame& frame, GLuint program)
{
    GlFunctions& gl = frame.gl;
    // Planes transform with the inverse transpose; only the enabled ones are passed,
    // packed, with their ClipSet index (a cap records it).
    const glm::dmat4 toView = glm::transpose(glm::inverse(frame.view));
    const ClipSet clips = frame.settings.clipSet();
    std::array<glm::vec4, kMaxClipPlanes> planes{};
    std::array<GLint, kMaxClipPlanes> planeSlots{}; // not "slots": a Qt macro
    GLint count = 0;
    for (int i = 0; i < kMaxClipPlanes; ++i) {
        const ClipPlane& plane = clips.planes[std::size_t(i)];
        if (!plane.enabled)
            continue;
        planes[std::size_t(count)] = glm::vec4(toView * plane.equation());
        planeSlots[std::size_t(count)] = i;
        ++count;
    }
    gl.glUniform1i(gl.glGetUniformLocation(program, "u_clipCount"), count);
    gl.glUniform4fv(gl.glGetUniformLocation(program, "u_clipPlanesView"), kMaxClipPlanes, glm::value_ptr(planes[0]));
    gl.glUniform1iv(gl.glGetUniformLocation(program, "u_clipSlot"), kMaxClipPlanes, planeSlots.data());
    gl.glUniform1f(gl.glGetUniformLocation(program, "u_zNear"), float(frame.camera.zNear));
    gl.glUniform1f(gl.glGetUniformLocation(program, "u_zFar"), float(frame.camera.zFar));
    if (frame.objectWindings)
        frame.objectWindings->bind(program);
}

namespace {

void setObjectWalkUniforms(const TrimFrame& frame, GLuint program)
{
    GlFunctions& gl = frame.gl;
    const TrimSettings& settings = frame.settings;
    std::array<GLint, kMaxCsgOperands> rules{};
    for (int o = 0; o < kMaxCsgOperands; ++o)
        rules[std::size_t(o)] = GLint(shaderRuleCode(settings.objectRule(o)));
    const CsgTruthTable table = csgTruthTable(settings.csg.expression); // all zero when empty
    const GLsizei objects = frame.objectWindings ? frame.objectWindings->objects() : 1;
    gl.glUniform1iv(gl.glGetUniformLocation(program, "u_objectRules"), objects, rules.data());
    gl.glUniform1i(gl.glGetUniformLocation(program, "u_csgEnabled"), settings.csg.enabled() ? 1 : 0);
    gl.glUniform1ui(gl.glGetUniformLocation(program, "u_carvedObjects"), csgSubtractedMask(settings.csg.expression));
    gl.glUniform1uiv(gl.glGetUniformLocation(program, "u_csgTable"), GLsizei(table.size()), table.data());
    gl.glUniform1i(gl.glGetUniformLocation(program, "u_highlightCollisions"), settings.highlight.collisions ? 1 : 0);
}

void setCapUniforms(const TrimFrame& frame, GLuint program)
{
    GlFunctions& gl = frame.gl;
    const CapSettings& cap = frame.settings.cap;
    const ClipSet clips = frame.settings.clipSet();
    std::array<glm::vec3, kMaxClipPlanes> normals{};
    for (int i = 0; i < kMaxClipPlanes; ++i) {
        const glm::dvec3 n = clips.planes[std::size_t(i)].normal;
        normals[std::size_t(i)] = glm::length(n) > 0.0 ? glm::vec3(glm::normalize(n)) : glm::vec3(0.0f);
    }
    const glm::mat4 viewToWorld(glm::inverse(frame.view));
    gl.glUniform1i(gl.glGetUniformLocation(program, "u_capPattern"), static_cast<GLint>(cap.pattern));
    gl.glUniform1f(gl.glGetUniformLocation(program, "u_capSpacing"),
                   std::isfinite(cap.spacing) ? float(cap.spacing) : 0.0f);
    gl.glUniform1f(gl.glGetUniformLocation(program, "u_capLineWidth"), float(std::clamp(cap.lineWidth, 0.0, 1.0)));
    gl.glUniformMatrix4fv(gl.glGetUniformLocation(program, "u_viewToWorld"), 1, GL_FALSE, glm::value_ptr(viewToWorld));
    gl.glUniform3fv(gl.glGetUniformLocation(program, "u_capNormalsWorld"), kMaxClipPlanes, glm::value_ptr(normals[0]));
}

// TransparencySettings, clamped as core/trim/transparency.h clamps them.
void setTransparencyUniforms(const TrimFrame& frame, GLuint program)
{
    GlFunctions& gl = frame.gl;
    const TransparencySettings& xray = frame.settings.transparency;
    auto nonNegative = [](double x) { return std::isfinite(x) ? float(std::max(x, 0.0)) : 0.0f; };
    auto unit = [](double x) { return std::isfinite(x) ? float(std::clamp(x, 0.0, 1.0)) : 0.0f; };
    gl.glUniform1i(gl.glGetUniformLocation(program, "u_xrayDisplay"), static_cast<GLint>(xray.display));
    gl.glUniform1f(gl.glGetUniformLocation(program, "u_xrayLayerAlpha"), unit(xray.layerAlpha));
    gl.glUniform1f(gl.glGetUniformLocation(program, "u_xrayGhostAlpha"), unit(xray.ghostAlpha));
    gl.glUniform1f(gl.glGetUniformLocation(program, "u_xrayDensity"), nonNegative(xray.density));
    gl.glUniform1f(gl.glGetUniformLocation(program, "u_xrayFresnel"), nonNegative(xray.fresnelExponent));
}

} // namespace

void setTrimWalkUniforms(const TrimFrame& frame, GLuint program)
{
    frame.gl.glUniform1i(frame.gl.glGetUniformLocation(program, "u_trimEnabled"), frame.settings.trimEnabled ? 1 : 0);
    frame.gl.glUniform1i(frame.gl.glGetUniformLocation(program, "u_rule"), shaderRuleCode(frame.settings.rule));
    frame.gl.glUniform1i(frame.gl.glGetUniformLocation(program, "u_dynamicRule"), frame.dynamicRule);
    frame.gl.glUniform1i(frame.gl.glGetUniformLocation(program, "u_referenceIsBase"), frame.referenceIsBase ? 1 : 0);
    setClipUniforms(frame, program);
    setObjectWalkUniforms(frame, program);
    setCapUniforms(frame, program);
    setTransparencyUniforms(frame, program);
}

void clearCountingState(TrimFrame& frame, PixelState& state)
{
    state.clear(frame.shaders);
    if (frame.objectWindings)
        frame.objectWindings->clear();
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
