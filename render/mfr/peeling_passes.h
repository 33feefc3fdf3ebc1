#pragma once
/// \file
/// The frame structure F2B and DUAL depth peeling share (thesis 2.4.2, 6.4, 8.1.2):
///
///     clear; repeat { geometry pass; walk pass } until no pixel is peeling; resolve
///
/// The geometry pass rasterises the scene once (the first one also counts the winding
/// index at the span start); the full-screen walk pass feeds what it peeled to each
/// pixel's trim walk and lets only the pixels still peeling pass. An occlusion query
/// (GL_ANY_SAMPLES_PASSED) over each walk pass is the condition of the next iteration's
/// conditional rendering, so the GPU skips every pass after the last pixel stopped, and
/// the CPU reads the queries a few passes late (no stall per pass) to stop issuing. The
/// number of geometry passes reported is the number the GPU really ran, read from the
/// queries. MethodParameters::maxPeelingPasses bounds the geometry passes; pixels still
/// peeling then are flagged unresolved by the resolve pass (shaders/peeling_resolve.frag).

#include "render/gl/gl_functions.h"
#include "render/gl/gl_objects.h"
#include "render/mfr/fragment_method.h"

#include <vector>

namespace trimlab::render {

class PeelingState;
struct TrimFrame;

/// The two programs of a peeling method (catalog names).
struct PeelingPrograms {
    const char* geometry; ///< scene.vert + the method's geometry pass, with `u_firstPass`
    const char* walk;     ///< fullscreen.vert + the method's walk pass, with `u_firstPass`
};

class PeelingPasses {
public:
    explicit PeelingPasses(GlFunctions& gl);

    /// Renders `frame` with `programs` on `state` (allocated and cleared here) and returns
    /// the frame's cost. Throws std::invalid_argument when maxPeelingPasses < 1 and
    /// GpuMemoryError when the state cannot be allocated.
    MethodStats render(TrimFrame& frame, PeelingState& state, const PeelingPrograms& programs);

private:
    /// Issues up to maxPeelingPasses iterations; returns how many were issued.
    int peel(TrimFrame& frame, PeelingState& state, const PeelingPrograms& programs);
    void geometryPass(TrimFrame& frame, PeelingState& state, GLuint program, bool first);
    void walkPass(TrimFrame& frame, PeelingState& state, GLuint program, bool first, GLuint query);
    void resolvePass(TrimFrame& frame, PeelingState& state);
    /// Geometry passes the GPU ran among the first `issued` iterations.
    int executedPasses(int issued);
    GLuint query(int iteration);
    bool queryResult(int iteration);

    GlFunctions& m_gl;
    std::vector<GlQuery> m_queries; ///< one per iteration, reused across frames
};

} // namespace trimlab::render
