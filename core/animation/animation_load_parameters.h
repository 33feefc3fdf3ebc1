#pragma once
/// \file
/// The options of loading a mesh animation (AnimationLoadOptions) that the batch verbs
/// offer, as rows of their parameter tables (core/util/parameter_spec.h): the rest pose,
/// and for glTF sources the animation and the sampling rate.

#include "core/animation/animation_loader.h"
#include "core/util/parameter_spec.h"

namespace trimlab::animation_load_parameters {

/// The most poses an index may name (a pose count beyond it is no animation anyone loads).
inline constexpr int kMaxPoseIndex = 1000000000;

inline constexpr ParameterSpec kRestPose{
    .id = "rest-pose",
    .flag = "rest-pose",
    .settingsKey = "",
    .kind = ParameterKind::Integer,
    .min = 0,
    .max = kMaxPoseIndex,
    .defaultValue = double(AnimationLoadOptions{}.restPose),
    .help = "Index of the rest pose among the loaded poses",
};

inline constexpr ParameterSpec kGltfAnimation{
    .id = "animation",
    .flag = "animation",
    .settingsKey = "",
    .kind = ParameterKind::Integer,
    .min = 0,
    .max = 1000000,
    .defaultValue = GltfAnimationOptions{}.animation,
    .help = "glTF only: which of the file's animations to sample, by index",
};

inline constexpr ParameterSpec kGltfFps{
    .id = "fps",
    .flag = "fps",
    .settingsKey = "",
    .kind = ParameterKind::Real,
    .min = 0.0,
    .max = 10000.0,
    .defaultValue = GltfAnimationOptions{}.fps,
    .help = "glTF only: sample the animation at this many frames per second",
    .minMeaning = "at its keyframes",
    .decimals = 3,
};

} // namespace trimlab::animation_load_parameters
