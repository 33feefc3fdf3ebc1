#pragma once
/// \file
/// The parameters of skinning an animation that users choose, for `trimlab skin` and the
/// Skinning panel alike (core/util/parameter_spec.h): the bones, the fit (the model a glTF
/// skin plays, LBS or DQS), its chain, the influences per vertex, the two corrections, and
/// the export (skin or morph targets, interpolation, frame rate). Defaults are the
/// panel's first start, which are the command line's (SkinningFitOptions itself defaults
/// to the plain LBS fit its callers build on).
///
/// One range where the command line and the panel disagreed: bones 1–65535, the most a
/// skin's JOINTS_0 can index (the panel stopped at 1000; the segmentation refuses more
/// segments than the mesh can make, with a message).

#include "core/skinning/skinning_fitter.h"
#include "core/skinning/skinning_gltf.h"
#include "core/util/parameter_spec.h"

#include <array>

namespace trimlab {

/// The fits users choose between: Rigid is SkinningFitOptions::fitExported (rigid joints
/// blended linearly, what a glTF skin plays), Lbs and Dqs its `method` otherwise.
enum class SkinningFitKind { Rigid, Lbs, Dqs };

[[nodiscard]] constexpr SkinningFitKind skinningFitKind(const SkinningFitOptions& options)
{
    if (options.fitExported)
        return SkinningFitKind::Rigid;
    return options.method == SkinningMethod::Dqs ? SkinningFitKind::Dqs : SkinningFitKind::Lbs;
}

/// Sets fitExported and method for `fit` (the rigid fit keeps method at Lbs).
constexpr void setSkinningFitKind(SkinningFitOptions& options, SkinningFitKind fit)
{
    options.fitExported = fit == SkinningFitKind::Rigid;
    options.method = fit == SkinningFitKind::Dqs ? SkinningMethod::Dqs : SkinningMethod::Lbs;
}

/// setSkinningFitKind with what the choice implies where the caller says nothing else, as
/// the command line applies it: the rigid fit always maps the rest pose to each pose (lbs
/// and dqs keep options.chain), and both corrections are on for the rigid fit, whose
/// decomposition iterates them, and off for lbs and dqs, where they are one pass that
/// rarely pays; a caller that was given corrections sets them afterwards.
constexpr void chooseSkinningFit(SkinningFitOptions& options, SkinningFitKind fit)
{
    setSkinningFitKind(options, fit);
    if (options.fitExported)
        options.chain = SkinningChain::RestToPose;
    options.vertexCorrections = options.fitExported;
    options.weightCorrections = options.fitExported;
}

} // namespace trimlab

namespace trimlab::skinning_parameters {

/// The most bones a skin can have (JOINTS_0 is an unsigned short).
inline constexpr int kMaxBones = 65535;

inline constexpr ParameterSpec kBones{
    .id = "bones",
    .flag = "bones",
    .settingsKey = "",
    .kind = ParameterKind::Integer,
    .min = 1,
    .max = kMaxBones,
    .defaultValue = 8,
    .help = "B, the bones to fit: the animation is segmented into exactly B parts",
    .required = true,
};

inline constexpr ChoiceValue kFits[] = {
    {"rigid", int(SkinningFitKind::Rigid), "Rigid joints (glTF skin)"},
    {"lbs", int(SkinningFitKind::Lbs), "LBS (affine bones)"},
    {"dqs", int(SkinningFitKind::Dqs), "DQS (rigid bones)"},
};

inline constexpr ParameterSpec kFit{
    .id = "method",
    .flag = "method",
    .settingsKey = "",
    .kind = ParameterKind::Choice,
    .defaultValue = int(SkinningFitKind::Rigid),
    .help = "rigid: rigid joints blended linearly, fitted with the weights and the rest pose, exactly what a glTF "
            "skin plays (the lowest exported error); lbs: affine bone transforms; dqs: rigid bones blended as dual "
            "quaternions (thesis chapter 4)",
    .choices = kFits,
};

inline constexpr ChoiceValue kChains[] = {
    {"pose-to-pose", int(SkinningChain::PoseToPose), "Pose to pose (p2p)"},
    {"rest-to-pose", int(SkinningChain::RestToPose), "Rest to pose (classical)"},
};

inline constexpr ParameterSpec kChain{
    .id = "chain",
    .flag = "chain",
    .settingsKey = "",
    .kind = ParameterKind::Choice,
    .defaultValue = int(SkinningChain::PoseToPose),
    .help = "lbs and dqs only: p2p-skinning fits each pose from the pose before it (thesis 4.1), the classical "
            "fit maps the rest pose to every pose; the rigid fit is always rest-to-pose",
    .choices = kChains,
};

inline constexpr ParameterSpec kInfluences{
    .id = "influences",
    .flag = "influences",
    .settingsKey = "",
    .kind = ParameterKind::Integer,
    .min = 1,
    .max = double(kMaxInfluences),
    .defaultValue = double(kDefaultInfluences),
    .help = "Most bones per vertex: 4 plays in every engine, 5 to 8 are written as JOINTS_1/WEIGHTS_1, which "
            "not every viewer reads; more than 4 are found only where weights are re-solved (the rigid fit, "
            "rest-to-pose LBS with corrections)",
};

/// The command line sets both corrections with one --corrections list (none, v, w, v,w).
inline constexpr ParameterSpec kWeightCorrections{
    .id = "weight-corrections",
    .flag = "",
    .settingsKey = "",
    .kind = ParameterKind::Boolean,
    .min = 0,
    .max = 1,
    .defaultValue = 1,
    .help = "Re-estimate the weights from the fitted transforms and refit (alternated with the fit where the "
            "weights are re-solved, else once and kept only when E_RMS does not rise)",
};

inline constexpr ParameterSpec kVertexCorrections{
    .id = "vertex-corrections",
    .flag = "",
    .settingsKey = "",
    .kind = ParameterKind::Boolean,
    .min = 0,
    .max = 1,
    .defaultValue = 1,
    .help = "Move the rest-pose vertices to lower the error (alternated like the weight corrections, or once)",
};

inline constexpr ChoiceValue kExports[] = {
    {"rigid", 0, "Skin"},
    {"morph", 1, "Morph targets"},
};

/// Choice values: SkinExportOptions::morphTargets.
inline constexpr ParameterSpec kExport{
    .id = "export",
    .flag = "export",
    .settingsKey = "",
    .kind = ParameterKind::Choice,
    .defaultValue = SkinExportOptions{}.morphTargets ? 1 : 0,
    .help = "rigid: a skin with one joint per bone; morph: one morph target per pose (exact, but larger)",
    .choices = kExports,
};

inline constexpr ChoiceValue kInterpolations[] = {
    {"linear", 0, "Linear"},
    {"step", 1, "Step"},
};

/// Choice values: SkinExportOptions::stepInterpolation.
inline constexpr ParameterSpec kInterpolation{
    .id = "interpolation",
    .flag = "interpolation",
    .settingsKey = "",
    .kind = ParameterKind::Choice,
    .defaultValue = SkinExportOptions{}.stepInterpolation ? 1 : 0,
    .help = "Keyframe interpolation of the exported skin: linear, or step (each pose held until the next)",
    .choices = kInterpolations,
};

/// The command line's; the panel exports at the Timeline's rate.
inline constexpr ParameterSpec kExportFps{
    .id = "fps",
    .flag = "fps",
    .settingsKey = "",
    .kind = ParameterKind::Real,
    .min = 0.001,
    .max = 10000.0,
    .defaultValue = 24.0,
    .help = "Frames per second of the exported animation (pose t at t/F seconds)",
    .decimals = 3,
};

inline constexpr std::array<const ParameterSpec*, 9> kTable{
    &kBones,  &kFit,           &kChain,    &kInfluences, &kWeightCorrections, &kVertexCorrections,
    &kExport, &kInterpolation, &kExportFps};
static_assert(isWellFormedTable(kTable));

} // namespace trimlab::skinning_parameters
