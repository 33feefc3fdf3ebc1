#pragma once
/// \file
/// What the Skeleton panel lets the user choose (skeleton_panel.h): the parameters of
/// every stage of skeleton extraction by mesh contraction (core/skeleton/
/// skeleton_extraction.h, Berenguer & Moreno III.A–D), the heat constant c of the
/// bone-heat weights (III.E) and the skinning used for posing, plus which stage the
/// viewport shows. Plain data; persisted by skeleton_settings_store.h.

#include "core/skinning/skinning_model.h"
#include "core/skeleton/skeleton_extraction.h"

namespace trimlab::ui {

/// What the viewport shows of the last run (the paper's Figs. 7–12).
enum class SkeletonStageView {
    Pose,         ///< the mesh skinned to the current pose, trim palette
    Contraction,  ///< the contracted mesh coloured by ‖L·V′‖ (Fig. 7)
    Mapping,      ///< the mesh coloured by the curve node that absorbed each vertex (Fig. 8)
    Segmentation, ///< the mesh coloured by the rig joint of each vertex (Fig. 10)
    Weights,      ///< the heat map of the selected bone's weight (Fig. 12)
};

struct SkeletonChoices {
    /// Stages A–D; targetNodes 20–40 in the panel (the paper's range), rootJoint −1 = automatic.
    SkeletonOptions extraction;
    /// c of H_jj = c/d² (bone_heat_terms.h); Pinocchio's 1.
    double heatConstant = 1.0;
    SkinningMethod skinning = SkinningMethod::Lbs;

    /// True when `other` needs a new contraction (stages A–C differ), false when only the
    /// node count or the root changed (selectRig + weights suffice).
    [[nodiscard]] bool needsContraction(const SkeletonChoices& other) const;
};

} // namespace trimlab::ui
