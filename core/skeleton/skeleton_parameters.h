#pragma once
/// \file
/// The parameters of skeleton extraction and rigging that users choose, for `trimlab
/// skeleton` and the Skeleton panel alike (core/util/parameter_spec.h): the contraction
/// (W_L⁰, s_L, the caps of W_L and W_H, iterations, ordering, solver), the simplification
/// (δ, w_a, w_b), the refinement, the selection (joints, root), the bone-heat constant c,
/// the skinning used for posing (panel only) and the Loop subdivision of the input
/// (command line only). Defaults are those of SkeletonOptions and BoneHeatTermOptions.
///
/// Ranges are what the panel offered, where the settings accepted more: a stored value
/// the form could not show was never a choice a user made. The joints are 2–10000: a rig
/// needs one bone (two joints); the paper's 20–40 is what suits an animation skeleton, not
/// a limit (a hand or a spider needs more), and the selection keeps at most the curve
/// skeleton's nodes anyway.

#include "core/skeleton/bone_heat_terms.h"
#include "core/skeleton/skeleton_extraction.h"
#include "core/skinning/skinning_model.h"
#include "core/util/parameter_spec.h"

#include <array>

namespace trimlab::skeleton_parameters {

inline constexpr ContractionOptions kContraction{};
inline constexpr SkeletonOptions kExtraction{};

inline constexpr ParameterSpec kInitialContractionWeight{
    .id = "contraction-weight",
    .flag = "contraction-weight",
    .settingsKey = "skeleton/initialContractionWeight",
    .kind = ParameterKind::Real,
    .min = 0.0,
    .max = 1000.0,
    .defaultValue = kContraction.initialContractionWeight,
    .help = "How strongly the first iteration pulls the surface inward (the paper's W_L0; its 0.001 sqrt(mean "
            "face area) spends the first ten iterations moving nothing)",
    .minMeaning = "automatic (1)",
    .decimals = 6,
    .step = 0.001,
};

inline constexpr ParameterSpec kContractionGrowth{
    .id = "contraction-growth",
    .flag = "contraction-growth",
    .settingsKey = "skeleton/contractionGrowth",
    .kind = ParameterKind::Real,
    .min = 1.1,
    .max = 10.0,
    .defaultValue = kContraction.contractionGrowth,
    .help = "How much stronger the inward pull gets each iteration (the paper's s_L)",
    .decimals = 2,
    .step = 0.1,
};

inline constexpr ParameterSpec kMaxContractionWeight{
    .id = "max-contraction-weight",
    .flag = "max-contraction-weight",
    .settingsKey = "skeleton/maxContractionWeight",
    .kind = ParameterKind::Real,
    .min = 1.0,
    .max = 1e6,
    .defaultValue = kContraction.maxContractionWeight,
    .help = "The strongest inward pull, as a multiple of the first (the cap of the paper's W_L)",
    .decimals = 1,
    .step = 100.0,
};

inline constexpr ParameterSpec kMaxAttractionWeight{
    .id = "max-attraction-weight",
    .flag = "max-attraction-weight",
    .settingsKey = "skeleton/maxAttractionWeight",
    .kind = ParameterKind::Real,
    .min = 1.0,
    .max = 1e7,
    .defaultValue = kContraction.maxAttractionWeight,
    .help = "How firmly vertices that stopped shrinking hold their place at most (the cap of the paper's W_H)",
    .decimals = 1,
    .step = 1000.0,
};

inline constexpr ParameterSpec kMaxIterations{
    .id = "max-iterations",
    .flag = "max-iterations",
    .settingsKey = "skeleton/maxIterations",
    .kind = ParameterKind::Integer,
    .min = 1,
    .max = 200,
    .defaultValue = kContraction.maxIterations,
    .help = "At most this many contraction solves",
};

inline constexpr ChoiceValue kOrderings[] = {
    {"amd", int(SparseOrdering::Amd), "AMD"},
    {"colamd", int(SparseOrdering::Colamd), "COLAMD"},
    {"metis", int(SparseOrdering::Metis), "METIS"},
};

inline constexpr ParameterSpec kOrdering{
    .id = "ordering",
    .flag = "ordering",
    .settingsKey = "skeleton/ordering",
    .kind = ParameterKind::Choice,
    .defaultValue = int(kContraction.ordering),
    .help = "Fill-reducing ordering of the sparse factorizations (paper Table I)",
    .choices = kOrderings,
};

inline constexpr ChoiceValue kSolvers[] = {
    {"cholmod", int(SparseBackend::Cholmod), "CHOLMOD"},
    {"ldlt", int(SparseBackend::EigenSimplicialLdlt), "LDLT (Eigen)"},
};

inline constexpr ParameterSpec kSolver{
    .id = "solver",
    .flag = "solver",
    .settingsKey = "skeleton/solver",
    .kind = ParameterKind::Choice,
    .defaultValue = int(kContraction.backend),
    .help = "Sparse Cholesky of the contraction and the weights: SuiteSparse's CHOLMOD or Eigen's SimplicialLDLT",
    .choices = kSolvers,
};

inline constexpr ParameterSpec kPreCollapseFraction{
    .id = "pre-collapse",
    .flag = "pre-collapse",
    .settingsKey = "skeleton/preCollapseFraction",
    .kind = ParameterKind::Real,
    .min = 0.0,
    .max = 0.1,
    .defaultValue = kExtraction.simplification.preCollapseFraction,
    .help = "Edges shorter than this fraction of the bounding-box diagonal collapse before the simplification "
            "(the paper's delta)",
    .minMeaning = "none",
    .decimals = 5,
    .step = 0.0005,
};

inline constexpr ParameterSpec kShapeWeight{
    .id = "shape-weight",
    .flag = "shape-weight",
    .settingsKey = "skeleton/shapeWeight",
    .kind = ParameterKind::Real,
    .min = 0.0,
    .max = 1000.0,
    .defaultValue = kExtraction.simplification.shapeWeight,
    .help = "How much keeping the curve's shape counts when collapsing edges (the paper's w_a)",
    .decimals = 3,
    .step = 0.1,
};

inline constexpr ParameterSpec kSamplingWeight{
    .id = "sampling-weight",
    .flag = "sampling-weight",
    .settingsKey = "skeleton/samplingWeight",
    .kind = ParameterKind::Real,
    .min = 0.0,
    .max = 1000.0,
    .defaultValue = kExtraction.simplification.samplingWeight,
    .help = "How much even spacing of the nodes counts when collapsing edges (the paper's w_b)",
    .decimals = 3,
    .step = 0.05,
};

inline constexpr ParameterSpec kRefine{
    .id = "refine",
    .flag = "refine",
    .settingsKey = "skeleton/refine",
    .kind = ParameterKind::Boolean,
    .min = 0,
    .max = 1,
    .defaultValue = kExtraction.refine ? 1.0 : 0.0,
    .help = "Refine the curve skeleton: centre its nodes, reach the tips, recover lost branches",
};

/// The most joints a rig may ask for.
inline constexpr int kMaxJoints = 10000;

inline constexpr ParameterSpec kTargetNodes{
    .id = "nodes",
    .flag = "nodes",
    .settingsKey = "skeleton/nodes",
    .kind = ParameterKind::Integer,
    .min = 2,
    .max = kMaxJoints,
    .defaultValue = kExtraction.targetNodes,
    .help = "Joints of the rig, the selection's target node count (the paper uses 20 to 40)",
};

/// Its upper bound is the joints' (the command line also refuses a root >= --nodes).
inline constexpr ParameterSpec kRootJoint{
    .id = "root",
    .flag = "root",
    .settingsKey = "skeleton/root",
    .kind = ParameterKind::Integer,
    .min = -1,
    .max = kMaxJoints - 1,
    .defaultValue = kExtraction.rootJoint,
    .help = "Root joint of the rig, an index below the number of joints",
    .minMeaning = "automatic",
};

inline constexpr ParameterSpec kHeatConstant{
    .id = "heat-constant",
    .flag = "heat-constant",
    .settingsKey = "skeleton/heatConstant",
    .kind = ParameterKind::Real,
    .min = 0.01,
    .max = 100.0,
    .defaultValue = BoneHeatTermOptions{}.heatConstant,
    .help = "How far each bone's influence spreads over the surface, the bone-heat constant c (Pinocchio: 1; the "
            "paper's 0.22 mimics heat in the volume)",
    .decimals = 3,
    .step = 0.05,
};

inline constexpr ChoiceValue kSkinnings[] = {
    {"lbs", int(SkinningMethod::Lbs), "Linear blend (LBS)"},
    {"dqs", int(SkinningMethod::Dqs), "Dual quaternion (DQS)"},
};

/// The panel's posing; the exported glTF always plays linear blend skinning.
inline constexpr ParameterSpec kPoseSkinning{
    .id = "skinning",
    .flag = "",
    .settingsKey = "skeleton/skinning",
    .kind = ParameterKind::Choice,
    .defaultValue = int(SkinningMethod::Lbs),
    .help = "How the panel deforms the mesh when a joint is posed",
    .choices = kSkinnings,
};

/// The command line's; the panel extracts from the mesh shown.
inline constexpr ParameterSpec kLoopSubdivisions{
    .id = "loop-subdivide",
    .flag = "loop-subdivide",
    .settingsKey = "",
    .kind = ParameterKind::Integer,
    .min = 0,
    .max = 6,
    .defaultValue = 0,
    .help = "Loop-subdivide the mesh this many times first (each level has 4 times the faces)",
};

inline constexpr std::array<const ParameterSpec*, 16> kTable{
    &kInitialContractionWeight,
    &kContractionGrowth,
    &kMaxContractionWeight,
    &kMaxAttractionWeight,
    &kMaxIterations,
    &kOrdering,
    &kSolver,
    &kPreCollapseFraction,
    &kShapeWeight,
    &kSamplingWeight,
    &kRefine,
    &kTargetNodes,
    &kRootJoint,
    &kHeatConstant,
    &kPoseSkinning,
    &kLoopSubdivisions,
};
static_assert(isWellFormedTable(kTable));

} // namespace trimlab::skeleton_parameters
