#pragma once
/// \file
/// A finished skinning fit as the Skinning panel keeps it: the core's result (model,
/// E_RMS, stage times), the original poses and the fitted model's reconstruction in double
/// precision (so an edit's error and the "Approximation" view need no recomputation of
/// the fit), and the bones' segmentation with one color per bone — all computed on a
/// worker and read-only afterwards.

#include "core/animation/color_wheel.h"
#include "core/animation/mesh_animation.h"
#include "core/skinning/skinning_fitter.h"
#include "core/skinning/skinning_reconstruction.h"
#include "core/util/task_control.h"
#include "core/animation/vertex_graph.h"

#include <memory>
#include <vector>

namespace trimlab::ui {

struct SkinningFit {
    SkinningFitResult result;
    std::vector<PosePositions> original;       ///< #P × #V, animationPositions(animation)
    std::vector<PosePositions> approximation;  ///< #P × #V, reconstructPoses(result.model)
    VertexLabeling bones;                      ///< #V labels: bone b = segment b
    std::vector<WheelColor> boneColors;        ///< one per bone (the segmentation's colors)
};

/// For a worker thread: fits `animation` with one bone per segment of `bones`
/// (fitSkinning's segmentation overload, its progress stages), then reconstructs every
/// pose (stage "reconstruction"). `boneColors`: one per segment. Throws what fitSkinning
/// throws (std::invalid_argument for a labeling that does not fit the animation,
/// OperationCancelled when asked to stop).
[[nodiscard]] std::shared_ptr<const SkinningFit> runSkinningFit(const MeshAnimation& animation, VertexLabeling bones,
                                                                std::vector<WheelColor> boneColors,
                                                                const SkinningFitOptions& options,
                                                                const TaskControl& control);

} // namespace trimlab::ui
