#pragma once
/// \file
/// GL state and uniforms every multi-fragment method sets the same way: the unordered
/// geometry pass that captures fragments, the full-screen resolve into the render target,
/// and the clip / trim-walk / output uniforms of shaders/common.

#include "render/gl/gl_functions.h"

namespace trimlab::render {

struct TrimFrame;

class PixelState;

/// Clip planes in view space, near and far plane (shaders/common/clip.glsl); binds the
/// frame's per-object winding buffer, if any (counting passes add to it).
void setClipUniforms(const TrimFrame& frame, GLuint program);
/// Rule and trim on/off (shaders/common/trim_walk.glsl), per-object rules and the CSG
/// truth table, highlights, the capping uniforms (shaders/common/cap.glsl, which also
/// needs the clip uniforms: they are set too) and the transparency uniforms
/// (shaders/common/transparency.glsl).
void setTrimWalkUniforms(const TrimFrame& frame, GLuint program);
/// Clears `state` (PixelState::clear) and the frame's per-object winding buffer, if any:
/// what a method does before each pass that counts the winding index.
void clearCountingState(TrimFrame& frame, PixelState& state);
/// Projection, viewport and pixel-ray parameters, vertex colors (trim_output.glsl).
void setOutputUniforms(const TrimFrame& frame, GLuint program);

/// Binds the render target and sets the state of a capturing geometry pass: every
/// fragment reaches the shader in any order (no depth test, no culling, no blending) and
/// no color is written (which also defuses llvmpipe's covered-tile trap, docs/llvmpipe-notes.md).
void beginCapturePass(TrimFrame& frame);
/// Restores color and depth writes after a capturing pass.
void endCapturePass(TrimFrame& frame);

/// Draws one full-screen triangle with `program` into the render target, writing color,
/// ids and depth (depth test ALWAYS). The caller has bound its inputs.
void drawResolvePass(TrimFrame& frame, GLuint program);

} // namespace trimlab::render
