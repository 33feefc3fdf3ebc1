#pragma once
/// \file
/// Binding points shared by every multi-fragment method; the GLSL side is
/// shaders/common/bindings.glsl (keep both identical).

#include <QtGui/qopengl.h>

namespace trimlab::render::binding {

// Image units.
inline constexpr GLuint kCounterImage = 0;
inline constexpr GLuint kSemaphoreImage = 1;
inline constexpr GLuint kWindingImage = 2;
inline constexpr GLuint kOverflowImage = 3;
inline constexpr GLuint kFragmentsImage = 4;
inline constexpr GLuint kHeadImage = 5;
inline constexpr GLuint kPeelDepthImage = 6;
inline constexpr GLuint kWalkImage = 7;

// Shader storage blocks (the scene uses 0-4, see gpu_scene.h).
inline constexpr GLuint kNodesStorage = 5;
inline constexpr GLuint kLinksStorage = 6;
inline constexpr GLuint kSharedCountersStorage = 7;
inline constexpr GLuint kDynamicStateStorage = 8;
inline constexpr GLuint kReferenceBitsStorage = 9;
inline constexpr GLuint kCharacterizationBitsStorage = 10;
inline constexpr GLuint kObjectWindingsStorage = 11;

} // namespace trimlab::render::binding
