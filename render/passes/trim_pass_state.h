#pragma once
/// \file
/// GL state and uniforms every multi-fragment method sets the same way: the unordered
/// geometry pass that captures fragments, the full-screen resolve into the render target,
/// and the clip / trim-walk / output uniforms of shaders/common.

#include "gl/gl_functions.h"

namespace trimlab::render {

struct TrimFrame;

/// Clip plane in view space, near plane (shaders/common/clip.glsl).
void setClipUniforms(const TrimFrame& frame, GLuint program);
/// Rule and trim on/off (shaders/common/trim_walk.glsl).
void setTrimWalkUniforms(const TrimFrame& frame, GLuint program);
/// Projection, viewport and pixel-ray parameters, vertex colors (trim_output.glsl).
void setOutputUniforms(const TrimFrame& frame, GLuint program);

/// Binds the render target and sets the state of a capturing geometry pass: every
/// fragment reaches the shader in any order (no depth test, no culling, no blending) and
/// no color is written (which also defuses llvmpipe's covered-tile trap, PLATFORM.md).
void beginCapturePass(TrimFrame& frame);
/// Restores color and depth writes after a capturing pass.
void endCapturePass(TrimFrame& frame);

/// Draws one full-screen triangle with `program` into the render target, writing color,
/// ids and depth (depth test ALWAYS). The caller has bound its inputs.
void drawResolvePass(TrimFrame& frame, GLuint program);

} // namespace trimlab::render
