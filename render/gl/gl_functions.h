#pragma once
/// \file
/// The OpenGL entry points the render layer uses: the 4.3 core function table of the
/// current context (Qt resolves it; no loader library needed).

#include <QOpenGLFunctions_4_3_Core>

namespace trimlab::render {

using GlFunctions = QOpenGLFunctions_4_3_Core;

/// The 4.3 core functions of the current context. Throws GlUnavailableError when there
/// is no current context or it cannot provide OpenGL 4.3 core.
[[nodiscard]] GlFunctions& currentGlFunctions();

} // namespace trimlab::render
