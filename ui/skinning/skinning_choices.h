#pragma once
/// \file
/// What the Skinning panel lets the user choose for a fit, as one value: the model a glTF
/// skin plays (rigid joints blended linearly, fitted by the skinning decomposition; the
/// default, for the lowest exported error), LBS or DQS, the
/// pose-to-pose (p2p-skinning, thesis 4.1.1) or classical rest-to-pose chain, and the
/// two corrections of thesis 4.1.2 (weights, eq. 4.13–4.15; rest-pose vertices, eq. 4.12 /
/// 4.16) — and where the bones come from: one per segment of the segmentation the
/// Segmentation panel shows, or a given number B (the animation re-segmented into exactly
/// B segments, skinning_bones.h).

#include "core/skinning/skinning_fitter.h"
#include "core/skinning/skinning_parameters.h"

namespace trimlab::ui {

enum class BoneSource {
    Segmentation, ///< the segments of the segmentation shown
    GivenCount,   ///< exactly `boneCount` segments of a new segmentation
};

/// Ranges and defaults are the rows of core/skinning/skinning_parameters.h.
struct SkinningChoices {
    BoneSource boneSource = BoneSource::Segmentation;
    int boneCount = int(skinning_parameters::kBones.defaultValue); ///< for BoneSource::GivenCount
    bool fitExported = true; ///< SkinningFitOptions::fitExported; `method` and `chain` then unused
    SkinningMethod method = SkinningMethod::Lbs;
    SkinningChain chain = SkinningChain(skinning_parameters::kChain.defaultValue);
    bool weightCorrections = skinning_parameters::kWeightCorrections.defaultValue != 0.0;
    bool vertexCorrections = skinning_parameters::kVertexCorrections.defaultValue != 0.0;
    /// Most bones per vertex (every fit keeps it; more than 4 only where the weights are
    /// re-solved, usesDecomposition): 4 plays everywhere; 5–8 are exported as JOINTS_1/WEIGHTS_1.
    int influences = int(skinning_parameters::kInfluences.defaultValue);

    /// The core options these choices ask for (every other option at its default).
    [[nodiscard]] SkinningFitOptions fitOptions() const
    {
        SkinningFitOptions options;
        options.fitExported = fitExported;
        options.method = method;
        options.chain = chain;
        options.weightCorrections = weightCorrections;
        options.vertexCorrections = vertexCorrections;
        options.decomposition.maxInfluences = std::size_t(influences);
        return options;
    }

    friend bool operator==(const SkinningChoices&, const SkinningChoices&) = default;
};

} // namespace trimlab::ui
