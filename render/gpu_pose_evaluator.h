#pragma once
/// \file
/// One GPU path for the poses the GPU can compute itself (shown_pose.h): a skinned pose
/// (frame/gpu_skinning.h) and a subdivision surface at its control points
/// (frame/gpu_subdivision.h) are both "an evaluator built once per source — the model or
/// the stencils —, then one evaluation per pose straight into the scene's buffers". The
/// viewport renderer keeps one evaluator, remembers a source whose evaluator failed (a
/// shader, OpenSubdiv's loader, memory, a model that does not fit the object) and uploads
/// the CPU's positions for it from then on, whichever kind of pose it is.

#include "render/frame/gpu_scene.h"
#include "render/gl/gl_functions.h"
#include "render/shown_pose.h"

#include <cstddef>
#include <memory>

namespace trimlab::render {

/// How the last pose reached the GPU.
enum class PoseEvaluation {
    Uploaded,       ///< the CPU's positions (no GPU source, or its evaluator failed)
    GpuSkinning,    ///< skinned on the GPU
    GpuSubdivision, ///< the subdivision surface evaluated on the GPU
};

class GpuPoseEvaluator {
public:
    virtual ~GpuPoseEvaluator() = default;
    /// Writes `pose` — of the source this evaluator was made for — into object `object` of
    /// `scene`, positions then normals, ordered before the scene's next use. Throws
    /// std::invalid_argument for a pose or object that does not fit, GlError.
    virtual void evaluate(GpuScene& scene, std::size_t object, const ShownPose& pose) = 0;
    [[nodiscard]] virtual PoseEvaluation kind() const = 0;
};

/// What `pose` is evaluated from on the GPU — its skinning model or its stencils — shared
/// by every pose of that source; nullptr for positions alone.
[[nodiscard]] std::shared_ptr<const void> gpuPoseSource(const ShownPose& pose);

/// The evaluator of `pose`'s source in the context of `gl` (current, also when it goes);
/// nullptr for positions alone. Throws what GpuSkinning and GpuSubdivision throw.
[[nodiscard]] std::unique_ptr<GpuPoseEvaluator> makeGpuPoseEvaluator(GlFunctions& gl, const ShownPose& pose);

} // namespace trimlab::render
