#pragma once
/// \file
/// The p2p-skinning pipeline of thesis chapter 4 as one call, with per-stage times:
/// weights from a segmentation (or given) → pose-to-pose (or classical) fit of every pose
/// → optional weight corrections and refit → optional rest-pose corrections → E_RMS.
///
/// How a panel or a batch verb drives it (on a worker thread; TaskControl carries
/// progress and the stop token):
///   MeshAnimation a = loadAnimation(source, loadOptions, control);   // animation_loader.h
///   AnimationSegmenter s(a, settings); s.run(control);               // chapter 3
///   SkinningFitResult r = fitSkinning(a, s.segment(h), options, control);
///   r.error.eRms, r.error.perPose, r.error.perVertex (heat map), r.times
///   reconstructPoses(r.model)                                        // the skinned animation
///   editPose(r.model, e, newPositions)                               // 4.1.3, propagates

#include "core/animation/mesh_animation.h"
#include "core/skinning/skinning_corrections.h"
#include "core/skinning/skinning_error.h"
#include "core/skinning/skinning_fit_options.h"
#include "core/skinning/skinning_model.h"
#include "core/skinning/skinning_weights.h"
#include "core/util/task_control.h"
#include "core/animation/vertex_graph.h"

namespace trimlab {

struct SkinningFitOptions {
    SkinningMethod method = SkinningMethod::Lbs;
    SkinningChain chain = SkinningChain::PoseToPose; ///< RestToPose: the classical fit
    PoseFitOptions poseFit;                          ///< solver, DQS iterations
    SkinningWeightOptions weights;                   ///< only for the segmentation overload
    bool weightCorrections = false;                  ///< eq. 4.13–4.15, then a refit
    bool vertexCorrections = false;                  ///< eq. 4.12 / 4.16, after the weights
    bool neighbourBones = true;                      ///< WeightCorrectionOptions::neighbourBones
    unsigned threads = 0;                            ///< 0 = hardware; results do not depend on it
};

/// Wall-clock milliseconds of each stage (0 for stages that did not run).
struct SkinningStageTimes {
    double weightsMs = 0.0;          ///< segmentation → weights
    double fitMs = 0.0;              ///< the first fit of every pose
    double weightCorrectionMs = 0.0; ///< new weights + the refit with them
    double vertexCorrectionMs = 0.0;
    double errorMs = 0.0;            ///< every reconstruction and E_RMS evaluation
    double totalMs = 0.0;
};

struct SkinningFitResult {
    SkinningModel model;
    SkinningError error;            ///< of `model`, after the corrections that were kept
    SkinningError uncorrectedError; ///< after the first fit, before any correction
    /// A correction is kept only when it does not raise E_RMS. The weight corrections
    /// minimise eq. 4.13 with the original previous poses (the thesis's assumption), not
    /// E_RMS itself, so on rare data the refit with them is worse; it is then dropped.
    bool weightCorrectionsKept = false;
    bool vertexCorrectionsKept = false;
    SkinningStageTimes times;
};

/// Fits `animation` (requireWellFormed) with the given initial weights (#V, convex; one
/// bone per proxy joint). The rest pose is animation.restPose. Progress stages "fit",
/// "weight corrections", "vertex corrections"; OperationCancelled leaves nothing behind.
/// Throws std::invalid_argument for a malformed animation or weights that do not match.
[[nodiscard]] SkinningFitResult fitSkinning(const MeshAnimation& animation, SkinningWeights weights,
                                            const SkinningFitOptions& options, const TaskControl& control = {});

/// The same with weights from `segmentation` (#V labels, one bone per segment) made
/// smooth by segmentationWeights (options.weights); stage "weights" first.
[[nodiscard]] SkinningFitResult fitSkinning(const MeshAnimation& animation, const VertexLabeling& segmentation,
                                            const SkinningFitOptions& options, const TaskControl& control = {});

} // namespace trimlab
