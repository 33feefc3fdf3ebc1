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
#include "core/skinning/skinning_decomposition.h"
#include "core/skinning/skinning_corrections.h"
#include "core/skinning/skinning_error.h"
#include "core/skinning/skinning_fit_options.h"
#include "core/skinning/skinning_model.h"
#include "core/skinning/skinning_weights.h"
#include "core/util/task_control.h"
#include "core/animation/vertex_graph.h"

namespace trimlab {

struct SkinningFitOptions {
    /// Fit the model a glTF skin plays — rigid joints blended linearly, rest-to-pose —
    /// by the decomposition of skinning_decomposition.h, whose weight and rest updates
    /// are the weight and vertex corrections computed against that model. The fitted
    /// model is then LBS, rest-to-pose, with rigid matrices: `method`, `chain`, `poseFit`
    /// and `neighbourBones` are not used. The lowest exported error; what `trimlab skin`
    /// and the Skinning panel use unless told otherwise.
    bool fitExported = false;
    /// Iterations, stopping rule and re-seeding of the decomposition, which runs for
    /// fitExported and for LBS rest-to-pose with corrections (usesDecomposition); its
    /// rigidJoints, updateWeights, updateRestPositions and threads come from the fields here.
    SkinningDecompositionOptions decomposition;
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
    double errorMs = 0.0; ///< every reconstruction and E_RMS evaluation
    double totalMs = 0.0;
};

struct SkinningFitResult {
    SkinningModel model;
    SkinningError error; ///< of `model`, after the corrections that were kept
    /// After the first fit, before any correction. For fitExported only the scalars eRms,
    /// eRmsDiagonal, rmse and diagonal are set (after the first joint block).
    SkinningError uncorrectedError;
    /// A correction is kept only when it does not raise E_RMS. The weight corrections
    /// minimise eq. 4.13 with the original previous poses (the thesis's assumption), not
    /// E_RMS itself, so on rare data the refit with them is worse; it is then dropped.
    bool weightCorrectionsKept = false;
    bool vertexCorrectionsKept = false;
    std::size_t iterations = 0; ///< decomposition iterations run (0: the thesis's one-shot fit)
    SkinningStageTimes times;
};

/// Whether fitSkinning runs the decomposition (skinning_decomposition.h): for fitExported,
/// and for LBS rest-to-pose with a correction, where the corrections are iterated with the
/// transforms until the error stops falling (for the pose-to-pose chain and for DQS they
/// are the thesis's single pass, eq. 4.12–4.17).
[[nodiscard]] bool usesDecomposition(const SkinningFitOptions& options);

/// Fits `animation` (requireWellFormed) with the given initial weights (#V, convex; one
/// bone per proxy joint), first cut to options.decomposition.maxInfluences per vertex,
/// which every later step keeps. The rest pose is animation.restPose. Progress stages "fit",
/// "weight corrections", "vertex corrections"; OperationCancelled leaves nothing behind.
/// Throws std::invalid_argument for a malformed animation or weights that do not match.
[[nodiscard]] SkinningFitResult fitSkinning(const MeshAnimation& animation, SkinningWeights weights,
                                            const SkinningFitOptions& options, const TaskControl& control = {});

/// The same with weights from `segmentation` (#V labels, one bone per segment) made
/// smooth by segmentationWeights (options.weights); stage "weights" first.
[[nodiscard]] SkinningFitResult fitSkinning(const MeshAnimation& animation, const VertexLabeling& segmentation,
                                            const SkinningFitOptions& options, const TaskControl& control = {});

} // namespace trimlab
