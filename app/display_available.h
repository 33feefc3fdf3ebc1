#pragma once
/// \file
/// Whether Qt can reach a display, which OpenGL needs on this platform (docs/llvmpipe-notes.md):
/// an X or Wayland display, or an explicitly chosen Qt platform plugin.

namespace trimlab::app {

[[nodiscard]] bool displayAvailable();

} // namespace trimlab::app
