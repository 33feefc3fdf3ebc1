#pragma once
/// \file
/// Everything one frame of a multi-fragment method needs, handed over by TrimRenderer.

#include "render/gl/gl_functions.h"
#include "render/mfr/fragment_method.h"

#include "core/trim/trim_settings.h"
#include "core/view/camera.h"

#include <glm/mat4x4.hpp>

#include <QStringList>

namespace trimlab::render {

class FrameCounters;
class GpuScene;
class ObjectWindingBuffer;
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
    /// Defines every program of the frame is built with on top of the method's own: the
    /// trim mode (e.g. DYNAMIC_RULES, DYNAMIC_CHARACTERIZE for the dynamic rules).
    QStringList modeDefines;
    /// Dynamic rules only (shaders/common/dynamic_walk.glsl): the set's rule and whether
    /// its reference is the base mesh (classified by settings.rule) or a characterization.
    int dynamicRule = 3;
    bool referenceIsBase = true;
    /// Per-object winding indices (CSG, collision highlighting: TrimSettings::
    /// perObjectWinding); nullptr when the frame does not need them. The programs are then
    /// built with OBJECT_WINDINGS <objects> among the mode defines.
    ObjectWindingBuffer* objectWindings = nullptr;
};

/// The program `name` with `defines` and the frame's mode defines (TRANSPARENCY only for
/// programs named "…_resolve": the capture passes do not depend on it).
[[nodiscard]] GLuint trimProgram(TrimFrame& frame, const QString& name, QStringList defines = {});

} // namespace trimlab::render
