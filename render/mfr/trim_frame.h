#pragma once
/// \file
/// Everything one frame of a multi-fragment method needs, handed over by TrimRenderer.

#include "gl/gl_functions.h"
#include "mfr/fragment_method.h"

#include "trim/trim_settings.h"
#include "view/camera.h"

#include <glm/mat4x4.hpp>

namespace trimlab::render {

class FrameCounters;
class GpuScene;
class RenderTarget;
class ShaderLibrary;
struct GlCapabilities;

struct TrimFrame {
    GlFunctions& gl;
    ShaderLibrary& shaders;
    const GlCapabilities& capabilities;
    GpuScene& scene;
    RenderTarget& target;
    FrameCounters& counters;
    const Camera& camera;
    const TrimSettings& settings;
    const MethodParameters& parameters;
    glm::dmat4 view;
    glm::dmat4 projection;
    int width;
    int height;
};

} // namespace trimlab::render
