#pragma once
/// \file
/// The whole skinning fit (thesis chapter 4), as both `trimlab skin` and the Skinning panel
/// run it: the proxy bones — the segments of a given segmentation, or the animation
/// segmented anew into exactly B segments (proxy_bones.h) — then fitSkinning with one
/// bone per segment (skinning_fitter.h), and the original poses and the fitted model's
/// reconstruction in double precision, which the error view, edits and exports read. One
/// function composes the stages, so the command line and the panel fit alike.

#include "core/animation/animation_segmenter.h"
#include "core/animation/color_wheel.h"
#include "core/animation/mesh_animation.h"
#include "core/animation/vertex_graph.h"
#include "core/skinning/proxy_bones.h"
#include "core/skinning/skinning_fitter.h"
#include "core/skinning/skinning_reconstruction.h"
#include "core/util/task_control.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

namespace trimlab {

/// Where the bones come from.
struct SkinningBoneSource {
    /// Set: one bone per segment of this segmentation, in its colours (one per label).
    std::optional<BoneSegmentation> segmentation;
    /// Otherwise: the animation segmented anew into exactly `count` segments with
    /// `segmenter`'s settings.
    std::size_t count = 0;
    SegmenterSettings segmenter;
};

/// The bones `trimlab skin` and the Python module fit: the animation segmented anew into
/// exactly `count` segments from pose partitions of `count` clusters each (the segmenter's
/// other settings at their defaults), on `threads` workers (0: every core).
[[nodiscard]] SkinningBoneSource segmentedBones(std::size_t count, unsigned threads);

struct SkinningPipelineOptions {
    SkinningFitOptions fit;
    /// Also reconstruct every pose from the fitted model (SkinningFit::approximation):
    /// what a viewer shows; an export measures its own file instead.
    bool reconstruct = true;
};

/// A finished fit; immutable once made, so that callers may share it.
struct SkinningFit {
    SkinningFitResult result;
    std::vector<PosePositions> original;      ///< #P × #V, animationPositions(animation)
    std::vector<PosePositions> approximation; ///< #P × #V, reconstructPoses(result.model); empty unless asked for
    VertexLabeling bones;                     ///< #V labels: bone b = segment b
    std::vector<WheelColor> boneColors;       ///< one per bone
    /// How segmenting anew reached the count (its segmentation is `bones`); nullopt for a
    /// given segmentation.
    std::optional<SegmentCountSearch> search;
    double segmentationMs = 0.0; ///< the segmenting anew, wall clock (0 for a given one)
};

/// The bones could not be made: segmenting anew into the count failed (a count above #V,
/// too few poses to partition, an over-segmentation that cannot reach the count). The
/// message is segmentIntoCount's; a caller prefixes the animation's name.
class SkinningBonesError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// For a worker thread: the bones of `source`, fitSkinning on `animation`, then (stage
/// "reconstruction") the original and, when asked, the reconstructed poses. Progress:
/// the segmenter's stages, fitSkinning's, "reconstruction". Throws SkinningBonesError as
/// above, std::invalid_argument for a given segmentation that does not fit the animation
/// or lacks a colour per segment, what fitSkinning throws, and OperationCancelled.
[[nodiscard]] std::shared_ptr<const SkinningFit> runSkinningFit(const MeshAnimation& animation,
                                                                const SkinningBoneSource& source,
                                                                const SkinningPipelineOptions& options,
                                                                const TaskControl& control = {});

} // namespace trimlab
