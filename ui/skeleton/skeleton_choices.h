#pragma once
/// \file
/// What the Skeleton panel lets the user choose (skeleton_panel.h): the parameters of
/// every stage of skeleton extraction by mesh contraction (core/skeleton/
/// skeleton_extraction.h, Berenguer & Moreno III.A–D), the heat constant c of the
/// bone-heat weights (III.E) and the skinning used for posing, plus which stage the
/// viewport shows. Plain data; ranges and defaults are the rows of
/// core/skeleton/skeleton_parameters.h; persisted by skeleton_settings_store.h.

#include "core/skeleton/skeleton_extraction.h"
#include "core/skeleton/skeleton_parameters.h"
#include "core/skinning/skinning_model.h"

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
    /// Stages A–D; rootJoint −1 = automatic.
    SkeletonOptions extraction;
    /// c of H_jj = c/d² (bone_heat_terms.h); Pinocchio's 1.
    double heatConstant = skeleton_parameters::kHeatConstant.defaultValue;
    SkinningMethod skinning = SkinningMethod(skeleton_parameters::kPoseSkinning.defaultValue);

    /// True when `other` needs a new contraction: any option of stages A–C differs, which
    /// is every option of `extraction` but the selection's node count and root (those
    /// alone need selectRig and the weights only).
    [[nodiscard]] bool needsContraction(const SkeletonChoices& other) const
    {
        SkeletonOptions curve = extraction;
        curve.targetNodes = other.extraction.targetNodes;
        curve.rootJoint = other.extraction.rootJoint;
        return !(curve == other.extraction);
    }

    friend bool operator==(const SkeletonChoices&, const SkeletonChoices&) = default;
};

} // namespace trimlab::ui
