#pragma once
/// \file
/// A subdivision surface evaluated on the GPU from its control points, written straight
/// into an object of a GpuScene (thesis 8.2: the self-trimmed surface may come from a
/// subdivision carried out on the GPU). OpenSubdiv's own GLSL compute evaluator
/// (Osd::GLComputeEvaluator over an Osd::GLStencilTableSSBO) applies the position stencils
/// of the CPU's SubdivisionSurface (subdivision_stencils.h) to the control points and writes
/// the output positions into the scene's position buffer at the object's first vertex;
/// then shaders/vertex_normals.comp recomputes the object's normals
/// (gpu_vertex_normals.h). An edit uploads only the #C control points: no output vertex
/// travels and none is touched by the CPU. The CPU's stencil evaluation stays the
/// reference (stills, exports, the history's frames).
///
/// Precision: OpenSubdiv's kernel is single precision (weights, control points and sums
/// are floats), the CPU's doubles rounded to float at the end; the two agree to float
/// rounding of the sums (render.gpu_subdivision measures it).
///
/// OpenSubdiv's GL code does not use Qt's function tables: libosdGPU loads the GL functions
/// itself, once per process, from libGL.so.1 through glXGetProcAddressARB, when the first
/// GLComputeEvaluator is made (an Osd::GLStencilTableSSBO made before that calls null
/// pointers). Those entry points dispatch to whatever context is current, so they work in
/// Qt's contexts (xcb and offscreen platforms under Xvfb, glvnd's GLX on NVIDIA). The
/// constructor checks first that libGL.so.1 and the entry points are there, because
/// OpenSubdiv would crash on a null pointer instead of reporting it.
///
/// GL state: OpenSubdiv's stencil kernel uses the storage binding points 0–15 of its own
/// (not render/gl/bindings.h's) and leaves them unbound with no program in use; every
/// TrimLab pass binds what it reads, so nothing depends on them.

#include "render/frame/gpu_scene.h"
#include "render/frame/gpu_vertex_normals.h"
#include "render/frame/subdivision_stencils.h"
#include "render/gl/gl_functions.h"
#include "render/gl/gl_objects.h"
#include "render/gl/shader_library.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace trimlab::render {

class GpuSubdivision {
public:
    /// Builds OpenSubdiv's evaluator (compiling its kernels) and uploads the stencils and
    /// the one-ring for the normals. The context must be current (also at destruction).
    /// Throws GlUnavailableError when OpenSubdiv's GL loader cannot work here (no
    /// libGL.so.1 or no glXGetProcAddressARB), ShaderBuildError when its kernel does not
    /// build (OpenSubdiv prints the log to stderr), GpuMemoryError, and
    /// std::invalid_argument for stencils that name a cage vertex ≥ #C or triangles that name
    /// a vertex ≥ #V_out.
    GpuSubdivision(GlFunctions& gl, const SubdivisionStencils& stencils);
    ~GpuSubdivision();
    GpuSubdivision(const GpuSubdivision&) = delete;
    GpuSubdivision& operator=(const GpuSubdivision&) = delete;

    /// Evaluates the surface at `controlPoints` (#C, object space) into object
    /// `objectIndex` of `scene` — positions, then normals — and orders it before the
    /// scene's next draw, storage read or buffer read. The object must be the surface's mesh
    /// (same vertex and triangle counts). Throws std::invalid_argument for another count of
    /// control points, a non-finite one, or an object that does not match.
    void evaluate(GpuScene& scene, std::size_t objectIndex, std::span<const glm::dvec3> controlPoints);

    [[nodiscard]] std::size_t cageVertexCount() const { return m_cageVertexCount; }
    [[nodiscard]] std::size_t vertexCount() const { return m_vertexCount; }
    /// GPU memory held: stencils, control points, one-ring.
    [[nodiscard]] std::size_t memoryBytes() const;

private:
    struct OpenSubdivObjects; // the evaluator and the stencil table, OpenSubdiv's types
    void requireObject(const GpuObjectGeometry& object, std::size_t objectIndex) const;
    void uploadControlPoints(std::span<const glm::dvec3> controlPoints);

    GlFunctions& m_gl;
    std::size_t m_cageVertexCount;
    std::size_t m_vertexCount;
    std::size_t m_triangleCount;
    std::unique_ptr<ShaderLibrary> m_shaders;
    std::unique_ptr<OpenSubdivObjects> m_osd;
    GlBuffer m_controlPoints;
    GpuVertexNormals m_normals;
    std::size_t m_stencilBytes = 0;
    std::vector<float> m_packed; ///< the control points as floats, reused per evaluation
};

} // namespace trimlab::render
